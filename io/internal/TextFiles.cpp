#include "io/internal/TextFiles.hpp"

#include "io/AtomicFile.hpp"

#include <QFile>
#include <QString>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace mcpp::io::internal {

Status writeFileAtomically(const std::string& path, const std::string& contents, Sync sync) {
    return io::writeFileAtomically(path, std::string_view(contents), sync);
}

std::string fileNotFound(const std::string& path) {
    const std::filesystem::path given(path);
    if (given.is_absolute())
        return path + ": file not found";
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(given, error);
    if (error)
        return path + ": file not found";
    return path + ": file not found (looked for " + absolute.lexically_normal().string() + ")";
}

Result<std::string> readWholeFile(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error))
        return Result<std::string>::failure(fileNotFound(path));
    if (std::filesystem::is_directory(path, error)) {
        return Result<std::string>::failure(path + ": is a folder, not a file");
    }
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly)) {
        return Result<std::string>::failure(path + ": cannot read: " + file.errorString().toStdString());
    }
    const QByteArray bytes = file.readAll();
    return std::string(bytes.constData(), static_cast<std::size_t>(bytes.size()));
}

std::string formatShortest(double value) {
    std::string text;
    appendShortest(text, value);
    return text;
}

std::string formatShortestFloat(float value) {
    std::string text;
    appendShortestFloat(text, value);
    return text;
}

void appendShortest(std::string& out, double value) {
    std::array<char, 64> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    out.append(buffer.data(), result.ptr);
}

void appendShortestFloat(std::string& out, float value) {
    std::array<char, 64> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    out.append(buffer.data(), result.ptr);
}

void appendRounded(std::string& out, double value, int decimals) {
    if (!std::isfinite(value)) {
        appendShortest(out, value);
        return;
    }
    // Fixed notation, trailing zeros dropped: 300000 as "300000", where the shortest text is "3e+05".
    // Files of many points round every field: powers of ten looked up, not computed each time.
    static constexpr std::array<double, 10> powersOfTen{1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
    std::array<char, 64> buffer{};
    const double scale = decimals >= 0 && decimals < int(powersOfTen.size())
                             ? powersOfTen[static_cast<std::size_t>(decimals)]
                             : std::pow(10.0, decimals);
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(),
                                      std::round(value * scale) / scale + 0.0, // + 0.0: never "-0"
                                      std::chars_format::fixed, decimals);
    char* end = result.ptr;
    if (decimals > 0) {
        while (end[-1] == '0')
            --end;
        if (end[-1] == '.')
            --end;
    }
    out.append(buffer.data(), end);
}

void appendFixed(std::string& out, double value, int decimals) {
    std::array<char, 64> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                      std::chars_format::fixed, decimals);
    out.append(buffer.data(), result.ptr);
}

double decimalDouble(float value) {
    const std::string text = formatShortestFloat(value);
    double parsed = value;
    std::from_chars(text.data(), text.data() + text.size(), parsed);
    return parsed;
}

std::string formatFixed(double value, int decimals) {
    std::string text;
    appendFixed(text, value, decimals);
    return text;
}

bool splitCsvLine(const std::string& line, std::vector<std::string>& fields) {
    fields.clear();
    std::string field;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char character = line[i];
        if (quoted) {
            if (character == '"') {
                if (i + 1 < line.size() && line[i + 1] == '"') {
                    field += '"';
                    ++i;
                } else {
                    quoted = false;
                }
            } else {
                field += character;
            }
        } else if (character == '"') {
            quoted = true;
        } else if (character == ',') {
            fields.push_back(field);
            field.clear();
        } else if (character != '\r') {
            field += character;
        }
    }
    fields.push_back(field);
    return !quoted;
}

std::string quoteCsvField(const std::string& field) {
    if (field.find_first_of(",\"\n\r") == std::string::npos && trimmed(field) == field)
        return field;
    std::string out = "\"";
    for (const char character : field) {
        if (character == '"')
            out += '"';
        out += character;
    }
    return out + "\"";
}

std::string trimmed(const std::string& text) {
    const auto begin = text.find_first_not_of(" \t\r\n");
    if (begin == std::string::npos)
        return {};
    const auto end = text.find_last_not_of(" \t\r\n");
    return text.substr(begin, end - begin + 1);
}

} // namespace mcpp::io::internal
