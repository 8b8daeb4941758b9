#include "io/internal/JsonValue.hpp"

#include "io/internal/TextFiles.hpp"

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

std::string JsonValue::toText() const {
    std::string out;
    write(out, 0);
    out += '\n';
    return out;
}

std::string formatJsonNumber(double value) {
    if (!std::isfinite(value))
        return "null";
    return formatShortest(value);
}

std::string quoteJsonString(const std::string& text) {
    std::string out = "\"";
    for (const char character : text) {
        const auto byte = static_cast<unsigned char>(character);
        switch (character) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        case '\b':
            out += "\\b";
            break;
        case '\f':
            out += "\\f";
            break;
        default:
            if (byte < 0x20) {
                char escaped[8];
                std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(byte));
                out += escaped;
            } else {
                out += character; // UTF-8 passes through unchanged
            }
        }
    }
    out += '"';
    return out;
}

void JsonValue::write(std::string& out, int indent) const {
    const std::string padding(static_cast<std::size_t>(indent + 2), ' ');
    const std::string closing(static_cast<std::size_t>(indent), ' ');
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
        out += formatJsonNumber(number_);
        return;
    case Kind::String:
        out += quoteJsonString(text_);
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
                items_[i].write(out, indent);
            }
            out += ']';
            return;
        }
        out += "[\n";
        for (std::size_t i = 0; i < items_.size(); ++i) {
            out += padding;
            items_[i].write(out, indent + 2);
            out += i + 1 < items_.size() ? ",\n" : "\n";
        }
        out += closing + "]";
        return;
    }
    case Kind::Object: {
        if (members_.empty()) {
            out += "{}";
            return;
        }
        out += "{\n";
        for (std::size_t i = 0; i < members_.size(); ++i) {
            out += padding + quoteJsonString(members_[i].first) + ": ";
            members_[i].second.write(out, indent + 2);
            out += i + 1 < members_.size() ? ",\n" : "\n";
        }
        out += closing + "}";
        return;
    }
    }
}

} // namespace mcpp::io::internal
