// Path → SVG path data: one absolute command per verb, numbers in the shortest text that reads
// back to the same double.
//
// std::to_chars without a precision produces the shortest decimal that round-trips (C++17
// [charconv.to.chars]); with correctly rounded reading on the other side (from_chars in the
// lexer) every finite double, −0 and subnormals included, comes back bit for bit. The text is
// then trimmed in ways the SVG grammar reads back identically: "0.5" → ".5", "1e+21" → "1e21",
// and the separator before a number is dropped where the grammar does not need it.
#include <algorithm>
#include <charconv>
#include <string>

#include "bezel/path.hpp"

namespace bezel {

namespace {

class Writer {
public:
    explicit Writer(int precision) : precision_(std::clamp(precision, 1, 17)) {}

    void command(char c) {
        out_.push_back(c);
        after_number_ = false;
    }

    void number(double v) {
        char buf[64];
        std::to_chars_result r = precision_ >= 17
                                     ? std::to_chars(buf, buf + sizeof buf, v)
                                     : std::to_chars(buf, buf + sizeof buf, v,
                                                     std::chars_format::general, precision_);
        char trimmed[64];
        std::string_view text = trim({buf, static_cast<std::size_t>(r.ptr - buf)}, trimmed);
        if (after_number_ && needs_separator(text)) out_.push_back(' ');
        out_.append(text);
        after_number_ = true;
        last_has_point_ = text.find('.') != std::string_view::npos;
        last_has_exponent_ = text.find('e') != std::string_view::npos;
    }

    void point(Point p) {
        number(p.x);
        number(p.y);
    }

    std::string take() { return std::move(out_); }

private:
    // Copies `text` into `out` (as large as text) without what the grammar does not need: a
    // zero before the point ("0.5" → ".5"), a '+' or leading zero in the exponent ("1e+07" →
    // "1e7").
    static std::string_view trim(std::string_view text, char* out) {
        std::size_t n = 0;
        for (std::size_t i = 0; i < text.size(); ++i) {
            char c = text[i];
            bool before_point = c == '0' && i + 1 < text.size() && text[i + 1] == '.' &&
                                (i == 0 || text[i - 1] == '-');
            bool exponent_sign = i > 0 && text[i - 1] == 'e';
            bool exponent_head = exponent_sign || (i > 1 && text[i - 2] == 'e' &&
                                                   (text[i - 1] == '-' || text[i - 1] == '+'));
            if (before_point) continue;
            if (c == '+' && exponent_sign) continue;
            if (c == '0' && exponent_head && i + 1 < text.size()) continue;
            out[n++] = c;
        }
        return {out, n};
    }

    // A number can follow the previous one directly when the lexer would end the previous one
    // there anyway: before a '-', and before a '.' once the previous number has its own point
    // or an exponent (which cannot take a fraction).
    bool needs_separator(std::string_view next) const {
        if (next.front() == '-') return false;
        if (next.front() == '.' && (last_has_point_ || last_has_exponent_)) return false;
        return true;
    }

    int precision_;
    std::string out_;
    bool after_number_ = false;
    bool last_has_point_ = false;
    bool last_has_exponent_ = false;
};

}  // namespace

std::string to_svg_path(const Path& path, int precision) {
    Writer w(precision);
    const std::vector<Point>& pts = path.points();
    std::size_t pi = 0;
    for (Verb v : path.verbs()) {
        switch (v) {
            case Verb::Move: w.command('M'); w.point(pts[pi++]); break;
            case Verb::Line: w.command('L'); w.point(pts[pi++]); break;
            case Verb::Quad:
                w.command('Q');
                for (int i = 0; i < 2; ++i) w.point(pts[pi++]);
                break;
            case Verb::Cubic:
                w.command('C');
                for (int i = 0; i < 3; ++i) w.point(pts[pi++]);
                break;
            case Verb::Close: w.command('Z'); break;
        }
    }
    return w.take();
}

}  // namespace bezel
