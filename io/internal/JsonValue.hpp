#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mcpp::io::internal {

// A JSON value whose objects keep their keys in insertion order, so files written from it have a fixed,
// readable layout (QJsonObject sorts keys) and byte-identical output for equal content.
class JsonValue {
  public:
    enum class Kind { Null, Boolean, Integer, Number, String, Array, Object };

    JsonValue() = default;
    JsonValue(bool value) : kind_(Kind::Boolean), boolean_(value) {}
    JsonValue(int value) : kind_(Kind::Integer), integer_(value) {}
    JsonValue(std::int64_t value) : kind_(Kind::Integer), integer_(value) {}
    JsonValue(double value) : kind_(Kind::Number), number_(value) {}
    JsonValue(std::string value) : kind_(Kind::String), text_(std::move(value)) {}
    JsonValue(const char* value) : kind_(Kind::String), text_(value) {}

    static JsonValue array() { return JsonValue(Kind::Array); }
    static JsonValue object() { return JsonValue(Kind::Object); }

    // Arrays: append. Objects: add a member (keys are not checked for duplicates).
    JsonValue& push(JsonValue value);
    JsonValue& add(std::string key, JsonValue value);

    // Two-space indentation; arrays of scalars stay on one line. Ends with a newline.
    enum class Layout {
        Indented,
        // Besides: an object of scalars and arrays of scalars on one line, as {"a": 1, "b": [2, 3]}. For
        // files of thousands of such records (an autopilot's mission items): a quarter fewer bytes, and
        // still a record a line.
        FlatObjectsOnOneLine
    };
    [[nodiscard]] std::string toText(Layout layout = Layout::Indented) const;

  private:
    explicit JsonValue(Kind kind) : kind_(kind) {}
    void write(std::string& out, int indent, Layout layout) const;
    void writeObjectOnOneLine(std::string& out) const;
    [[nodiscard]] bool isScalar() const { return kind_ != Kind::Array && kind_ != Kind::Object; }
    [[nodiscard]] bool isFlatObject() const;

    Kind kind_ = Kind::Null;
    bool boolean_ = false;
    std::int64_t integer_ = 0;
    double number_ = 0.0;
    std::string text_;
    std::vector<JsonValue> items_;
    std::vector<std::pair<std::string, JsonValue>> members_;
};

// Appended to `out`, so a big file's text is built without temporary strings: the shortest text that reads
// back as the same double ("30", "0.1", "1e+20"), "null" for NaN and infinities; a quoted, escaped string.
void appendJsonNumber(std::string& out, double value);
void appendJsonString(std::string& out, std::string_view text);

} // namespace mcpp::io::internal
