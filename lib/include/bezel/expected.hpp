// bezel/expected.hpp — the result type every fallible public function returns.
//
// Exceptions never cross bezel's public API for bad input (the one exception thrown,
// BadExpectedAccess below, marks a caller's programming error: a failed result used as a value).
// A function that can fail on its input returns
// `Expected<T>`: either a value or an `Error` whose message names the input and what is wrong
// with it ("fonts/x.ttf: FreeType error 0x02 (cannot open resource)", "path data offset 7:
// expected a number"). C++17 has no std::expected; this is the small subset we need.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// What went wrong and with which input. `message` is one line, meant for a human, and already
// names the input; callers print it as is.
struct Error {
    std::string message;
};

// Thrown by an Expected accessed against its state: value(), `*` or `->` of one that holds an
// Error (what() is "bezel: no value: " then the Error's message, so the failure says what went
// wrong with which input), or error() of one that holds a value. A programming error, not an
// input error: it fails loudly, in every build type, instead of the std::bad_variant_access (or
// undefined behaviour) of an unchecked access. Input errors never throw: check ok() first.
class BadExpectedAccess : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

template <typename T>
class [[nodiscard]] Expected {
public:
    Expected(T value) : v_(std::move(value)) {}        // NOLINT: implicit by design
    Expected(Error error) : v_(std::move(error)) {}    // NOLINT: implicit by design

    bool ok() const { return v_.index() == 0; }
    explicit operator bool() const { return ok(); }

    // Precondition: ok(). Otherwise throws BadExpectedAccess carrying the Error's message.
    T& value() & { check_value(); return *std::get_if<0>(&v_); }
    const T& value() const& { check_value(); return *std::get_if<0>(&v_); }
    T&& value() && { check_value(); return std::move(*std::get_if<0>(&v_)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    // Precondition: !ok(). Otherwise throws BadExpectedAccess.
    const Error& error() const {
        if (ok()) throw BadExpectedAccess("bezel: error() of an Expected that holds a value");
        return *std::get_if<1>(&v_);
    }

private:
    void check_value() const {
        if (!ok()) throw BadExpectedAccess("bezel: no value: " + std::get_if<1>(&v_)->message);
    }
    std::variant<T, Error> v_;
};

// For functions that produce nothing but can fail.
struct Unit {};
using Status = Expected<Unit>;
inline Status ok_status() { return Unit{}; }

}  // namespace bezel
#pragma GCC visibility pop
