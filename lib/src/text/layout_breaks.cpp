// Line breaks and grapheme clusters by ICU's break iterators (layout_breaks.hpp).
#include "text/layout_breaks.hpp"

#include <unicode/ubrk.h>
#include <unicode/utf16.h>

namespace bezel::text_detail {

bool is_break_space(char32_t c) {
    return c == 0x20 || c == 0x09 || c == 0x1680 || (c >= 0x2000 && c <= 0x200A && c != 0x2007) ||
           c == 0x205F || c == 0x3000;
}

namespace {

struct IteratorCloser {
    void operator()(UBreakIterator* it) const { ubrk_close(it); }
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
        UErrorCode status = U_ZERO_ERROR;
        it.reset(ubrk_open(type, "", nullptr, 0, &status));
        if (U_FAILURE(status) || !it) {
            it.reset();
            return Error{std::string("ICU break iterator: ") + u_errorName(status)};
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
        UErrorCode status = U_ZERO_ERROR;
        ubrk_setText(it, reinterpret_cast<const UChar*>(utf16.data()),
                     static_cast<std::int32_t>(utf16.size()), &status);
        if (U_FAILURE(status)) return Error{std::string("ICU break iterator: ") + u_errorName(status)};
        for (std::int32_t b = ubrk_first(it); b != UBRK_DONE; b = ubrk_next(it)) {
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

}  // namespace bezel::text_detail
