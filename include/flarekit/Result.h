// SPDX-License-Identifier: Apache-2.0
// Result<T>: a value or an Error. The library reports every failure through it and never
// throws across its API; only the CLI turns errors into messages and exit codes.
#pragma once

#include <string>
#include <utility>
#include <variant>

namespace flarekit {

enum class ErrorCode {
    InvalidInput,  //!< the caller's data is wrong: bad file, field, size, value (CLI exit 2)
    Io,            //!< a file could not be read or written (CLI exit 2)
    Internal,      //!< a bug or an environment failure inside flarekit (CLI exit 1)
    Interrupted,   //!< stopped by SIGINT/SIGTERM at a safe point (CLI exit 128 + signal)
};

struct Error {
    ErrorCode code = ErrorCode::Internal;
    std::string message;  //!< one line: "file: field: what was expected, got what"
};

inline Error invalidInput(std::string message) {
    return {ErrorCode::InvalidInput, std::move(message)};
}
inline Error ioError(std::string message) {
    return {ErrorCode::Io, std::move(message)};
}
inline Error internalError(std::string message) {
    return {ErrorCode::Internal, std::move(message)};
}

template <typename T>
class [[nodiscard]] Result {
  public:
    Result(T value) : m_state(std::move(value)) {}      // NOLINT(google-explicit-constructor)
    Result(Error error) : m_state(std::move(error)) {}  // NOLINT(google-explicit-constructor)

    bool ok() const { return std::holds_alternative<T>(m_state); }
    explicit operator bool() const { return ok(); }

    T& value() & { return std::get<T>(m_state); }
    const T& value() const& { return std::get<T>(m_state); }
    T&& value() && { return std::get<T>(std::move(m_state)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const { return std::get<Error>(m_state); }

  private:
    std::variant<T, Error> m_state;
};

struct Ok {};  //!< the value of a Result that carries no data
using Status = Result<Ok>;

}  // namespace flarekit
