#include "io/internal/JsonValue.hpp"

#include "io/internal/TextFiles.hpp"

#include <array>
#include <cmath>
#include <cstdio>

namespace mcpp::io::internal {

JsonValue& JsonValue::push(JsonValue value) {
    items_.push_back(std::move(value));
    return items_.back();
}

JsonValue& JsonValue::add(std::string key, JsonValue value) {
    members_.emplace_back(std::move(key), std::move(value));
    return members_.back().second;
}

std::string JsonValue::toText(Layout layout) const {
    std::string out;
    write(out, 0, layout);
    out += '\n';
    return out;
}

namespace {

char escapeLetter(char character) {
    switch (character) {
    case '"':
        return '"';
    case '\\':
        return '\\';
    case '\n':
        return 'n';
    case '\r':
        return 'r';
    case '\t':
        return 't';
    case '\b':
        return 'b';
    case '\f':
        return 'f';
    default:
        return 0;
    }
}

bool needsEscape(char character) {
    return character == '"' || character == '\\' || static_cast<unsigned char>(character) < 0x20;
}

} // namespace

void appendJsonNumber(std::string& out, double value) {
    if (!std::isfinite(value)) {
        out += "null";
        return;
    }
    appendShortest(out, value);
}

void appendJsonString(std::string& out, std::string_view text) {
    out += '"';
    // Most text needs no escape and is copied in runs.
    std::size_t runStart = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (!needsEscape(text[i]))
            continue; // UTF-8 passes through unchanged
        out.append(text.substr(runStart, i - runStart));
        runStart = i + 1;
        if (const char letter = escapeLetter(text[i]); letter != 0) {
            out += '\\';
            out += letter;
        } else {
            std::array<char, 8> escaped{};
            std::snprintf(escaped.data(), escaped.size(), "\\u%04x",
                          static_cast<unsigned>(static_cast<unsigned char>(text[i])));
            out += escaped.data();
        }
    }
    out.append(text.substr(runStart));
    out += '"';
}

bool JsonValue::isFlatObject() const {
    if (kind_ != Kind::Object || members_.empty())
        return false;
    for (const auto& [key, value] : members_) {
        if (value.kind_ == Kind::Object)
            return false;
        for (const JsonValue& item : value.items_)
            if (!item.isScalar())
                return false;
    }
    return true;
}

void JsonValue::writeObjectOnOneLine(std::string& out) const {
    out += '{';
    for (std::size_t i = 0; i < members_.size(); ++i) {
        if (i > 0)
            out += ", ";
        appendJsonString(out, members_[i].first);
        out += ": ";
        members_[i].second.write(out, 0, Layout::Indented); // a scalar or an array of scalars: one line
    }
    out += '}';
}

void JsonValue::write(std::string& out, int indent, Layout layout) const {
    const auto padding = static_cast<std::size_t>(indent + 2);
    switch (kind_) {
    case Kind::Null:
        out += "null";
        return;
    case Kind::Boolean:
        out += boolean_ ? "true" : "false";
        return;
    case Kind::Integer:
        out += std::to_string(integer_);
        return;
    case Kind::Number:
        appendJsonNumber(out, number_);
        return;
    case Kind::String:
        appendJsonString(out, text_);
        return;
    case Kind::Array: {
        if (items_.empty()) {
            out += "[]";
            return;
        }
        bool allScalar = true;
        for (const JsonValue& item : items_)
            allScalar = allScalar && item.isScalar();
        if (allScalar) {
            out += '[';
            for (std::size_t i = 0; i < items_.size(); ++i) {
                if (i > 0)
                    out += ", ";
                items_[i].write(out, indent, layout);
            }
            out += ']';
            return;
        }
        out += "[\n";
        for (std::size_t i = 0; i < items_.size(); ++i) {
            out.append(padding, ' ');
            items_[i].write(out, indent + 2, layout);
            out += i + 1 < items_.size() ? ",\n" : "\n";
        }
        out.append(static_cast<std::size_t>(indent), ' ');
        out += ']';
        return;
    }
    case Kind::Object: {
        if (members_.empty()) {
            out += "{}";
            return;
        }
        if (layout == Layout::FlatObjectsOnOneLine && isFlatObject()) {
            writeObjectOnOneLine(out);
            return;
        }
        out += "{\n";
        for (std::size_t i = 0; i < members_.size(); ++i) {
            out.append(padding, ' ');
            appendJsonString(out, members_[i].first);
            out += ": ";
            members_[i].second.write(out, indent + 2, layout);
            out += i + 1 < members_.size() ? ",\n" : "\n";
        }
        out.append(static_cast<std::size_t>(indent), ' ');
        out += '}';
        return;
    }
    }
}

} // namespace mcpp::io::internal
