// Line breaks and grapheme clusters by ICU's break iterators (layout_breaks.hpp).
#include "text/layout_breaks.hpp"

#include <dlfcn.h>
#include <unicode/ubrk.h>
#include <unicode/uchar.h>
#include <unicode/utf16.h>

#include <mutex>
#include <string>
#include <type_traits>

namespace bezel::text_detail {

bool is_break_space(char32_t c) {
    return c == 0x20 || c == 0x09 || c == 0x1680 || (c >= 0x2000 && c <= 0x200A && c != 0x2007) ||
           c == 0x205F || c == 0x3000;
}

namespace {

// ICU is loaded when text is first broken into lines or clusters, not when bezel starts: mapping
// libicuuc, its 30 MB data library and the shared C++ runtime it needs costs a process about as
// much as rendering a short line, and a page that is not wrapped never breaks lines. The
// functions are ICU's C API of the version bezel was compiled against (their names carry the
// version, as ICU's headers rename them: ubrk_open is ubrk_open_72).
#define BEZEL_ICU_NAME2(x) #x
#define BEZEL_ICU_NAME(x) BEZEL_ICU_NAME2(x)

struct IcuApi {
    decltype(&ubrk_open) open = nullptr;
    decltype(&ubrk_close) close = nullptr;
    decltype(&ubrk_setText) set_text = nullptr;
    decltype(&ubrk_first) first = nullptr;
    decltype(&ubrk_next) next = nullptr;
    decltype(&u_errorName) error_name = nullptr;
    decltype(&u_hasBinaryProperty) has_property = nullptr;
    std::string failure;   // why ICU could not be loaded; empty when it was
};

const IcuApi& icu() {
    static IcuApi api;
    static std::once_flag once;
    std::call_once(once, [] {
        const char* library = "libicuuc.so." BEZEL_ICU_NAME(U_ICU_VERSION_MAJOR_NUM);
        void* handle = dlopen(library, RTLD_NOW | RTLD_LOCAL);
        if (handle == nullptr) {
            api.failure = std::string("cannot load ICU (") + library + "), which line breaking needs: " +
                          dlerror();
            return;
        }
        auto load = [&](auto& fn, const char* name) {
            fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(dlsym(handle, name));
            if (fn == nullptr && api.failure.empty())
                api.failure = std::string(library) + " has no " + name;
        };
        load(api.open, BEZEL_ICU_NAME(ubrk_open));
        load(api.close, BEZEL_ICU_NAME(ubrk_close));
        load(api.set_text, BEZEL_ICU_NAME(ubrk_setText));
        load(api.first, BEZEL_ICU_NAME(ubrk_first));
        load(api.next, BEZEL_ICU_NAME(ubrk_next));
        load(api.error_name, BEZEL_ICU_NAME(u_errorName));
        load(api.has_property, BEZEL_ICU_NAME(u_hasBinaryProperty));
        // The library stays loaded for the life of the process: iterators may outlive any caller.
    });
    return api;
}

struct IteratorCloser {
    void operator()(UBreakIterator* it) const { icu().close(it); }
};
using Iterator = std::unique_ptr<UBreakIterator, IteratorCloser>;

}  // namespace

struct UnicodeBreaks::Impl {
    Iterator line, character;
    std::u16string utf16;
    std::vector<std::uint32_t> index_of_unit;   // UTF-16 unit → code point index (n at the end)

    // Opens `it` of `type` on first use (the root locale: UAX #14 / #29's defaults).
    Status open(Iterator& it, UBreakIteratorType type) {
        if (it) return ok_status();
        const IcuApi& api = icu();
        if (!api.failure.empty()) return Error{api.failure};
        UErrorCode status = U_ZERO_ERROR;
        it.reset(api.open(type, "", nullptr, 0, &status));
        if (U_FAILURE(status) || !it) {
            it.reset();
            return Error{std::string("ICU break iterator: ") + api.error_name(status)};
        }
        return ok_status();
    }

    // Sets out[k] = 1 where `it` has a boundary before text[k], 0 elsewhere, out[0] = `first`.
    Status boundaries(UBreakIterator* it, const char32_t* text, std::size_t n, bool first,
                      std::vector<std::uint8_t>& out) {
        out.assign(n, 0);
        if (n == 0) return ok_status();
        utf16.clear();
        index_of_unit.clear();
        for (std::size_t k = 0; k < n; ++k) {
            const char32_t c = text[k];
            if (c >= 0x10000) {
                utf16.push_back(static_cast<char16_t>(U16_LEAD(c)));
                utf16.push_back(static_cast<char16_t>(U16_TRAIL(c)));
                index_of_unit.insert(index_of_unit.end(), 2, static_cast<std::uint32_t>(k));
            } else {
                utf16.push_back(static_cast<char16_t>(c));
                index_of_unit.push_back(static_cast<std::uint32_t>(k));
            }
        }
        index_of_unit.push_back(static_cast<std::uint32_t>(n));
        const IcuApi& api = icu();
        UErrorCode status = U_ZERO_ERROR;
        api.set_text(it, reinterpret_cast<const UChar*>(utf16.data()),
                     static_cast<std::int32_t>(utf16.size()), &status);
        if (U_FAILURE(status))
            return Error{std::string("ICU break iterator: ") + api.error_name(status)};
        for (std::int32_t b = api.first(it); b != UBRK_DONE; b = api.next(it)) {
            const std::uint32_t k = index_of_unit[static_cast<std::size_t>(b)];
            if (k > 0 && k < n) out[k] = 1;
        }
        out[0] = first ? 1 : 0;
        return ok_status();
    }
};

UnicodeBreaks::UnicodeBreaks() : impl_(std::make_unique<Impl>()) {}
UnicodeBreaks::~UnicodeBreaks() = default;

Status UnicodeBreaks::line_breaks(const char32_t* text, std::size_t n,
                                  std::vector<std::uint8_t>& out) {
    if (auto ok = impl_->open(impl_->line, UBRK_LINE); !ok) return ok;
    return impl_->boundaries(impl_->line.get(), text, n, false, out);
}

Status UnicodeBreaks::grapheme_starts(const char32_t* text, std::size_t n,
                                      std::vector<std::uint8_t>& out) {
    if (auto ok = impl_->open(impl_->character, UBRK_CHARACTER); !ok) return ok;
    return impl_->boundaries(impl_->character.get(), text, n, true, out);
}

Expected<bool> has_unicode_property(char32_t cp, UnicodeProperty property) {
    const IcuApi& api = icu();
    if (!api.failure.empty()) return Error{api.failure};
    UProperty which = UCHAR_EMOJI_PRESENTATION;
    switch (property) {
        case UnicodeProperty::EmojiPresentation: which = UCHAR_EMOJI_PRESENTATION; break;
    }
    return api.has_property(static_cast<UChar32>(cp), which) != 0;
}

}  // namespace bezel::text_detail
