#pragma once

#include <string>
#include <utility>
#include <variant>

namespace mcpp::io {

// What went wrong, in one line naming the file, field or flag and the problem.
struct IoError {
    std::string message;
};

// A value or an error; io never throws across its public interface.
template <typename T> class [[nodiscard]] Result {
  public:
    Result(T value) : state_(std::move(value)) {}
    Result(IoError error) : state_(std::move(error)) {}
    static Result failure(std::string message) { return Result(IoError{std::move(message)}); }

    [[nodiscard]] bool ok() const { return std::holds_alternative<T>(state_); }
    explicit operator bool() const { return ok(); }
    [[nodiscard]] T& value() { return std::get<T>(state_); }
    [[nodiscard]] const T& value() const { return std::get<T>(state_); }
    [[nodiscard]] const std::string& error() const { return std::get<IoError>(state_).message; }

  private:
    std::variant<T, IoError> state_;
};

// Success or an error, for operations that return nothing.
class [[nodiscard]] Status {
  public:
    Status() = default;
    Status(IoError error) : error_(std::move(error.message)), failed_(true) {}
    static Status failure(std::string message) { return Status(IoError{std::move(message)}); }

    [[nodiscard]] bool ok() const { return !failed_; }
    explicit operator bool() const { return ok(); }
    [[nodiscard]] const std::string& error() const { return error_; }

  private:
    std::string error_;
    bool failed_ = false;
};

} // namespace mcpp::io
