// bezel/expected.hpp — the result type every fallible public function returns.
//
// Exceptions never cross bezel's public API. A function that can fail on its input returns
// `Expected<T>`: either a value or an `Error` whose message names the input and what is wrong
// with it ("fonts/x.ttf: FreeType error 0x02 (cannot open resource)", "path data offset 7:
// expected a number"). C++17 has no std::expected; this is the small subset we need.
#pragma once

#include <cassert>
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

template <typename T>
class [[nodiscard]] Expected {
public:
    Expected(T value) : v_(std::move(value)) {}        // NOLINT: implicit by design
    Expected(Error error) : v_(std::move(error)) {}    // NOLINT: implicit by design

    bool ok() const { return v_.index() == 0; }
    explicit operator bool() const { return ok(); }

    // Precondition: ok(). Checked by assert in debug builds.
    T& value() & { assert(ok()); return std::get<0>(v_); }
    const T& value() const& { assert(ok()); return std::get<0>(v_); }
    T&& value() && { assert(ok()); return std::get<0>(std::move(v_)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    // Precondition: !ok().
    const Error& error() const { assert(!ok()); return std::get<1>(v_); }

private:
    std::variant<T, Error> v_;
};

// For functions that produce nothing but can fail.
struct Unit {};
using Status = Expected<Unit>;
inline Status ok_status() { return Unit{}; }

}  // namespace bezel
#pragma GCC visibility pop
