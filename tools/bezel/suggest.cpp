#include "suggest.hpp"

#include <algorithm>

namespace bezel::cli {

std::size_t edit_distance(const std::string& a, const std::string& b) {
    // d[i][j]: edits from a[0, i) to b[0, j); three rows suffice for the transposition case.
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::size_t> before(m + 1), prev(m + 1), cur(m + 1);
    for (std::size_t j = 0; j <= m; ++j) prev[j] = j;
    for (std::size_t i = 1; i <= n; ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                cur[j] = std::min(cur[j], before[j - 2] + 1);
        }
        before.swap(prev);
        prev.swap(cur);
    }
    return prev[m];
}

std::optional<std::string> closest_name(const std::string& typed,
                                        const std::vector<std::string>& names) {
    std::optional<std::string> best;
    std::size_t best_distance = 0;
    for (const std::string& name : names) {
        if (name.size() <= 2) continue;
        const std::size_t d = edit_distance(typed, name);
        const std::size_t allowed = name.size() <= 4 ? 1 : 2;
        if (d == 0 || d > allowed) continue;
        if (!best || d < best_distance) {
            best = name;
            best_distance = d;
        }
    }
    if (best) return best;
    std::optional<std::string> prefix_of;
    for (const std::string& name : names) {
        if (name.size() <= typed.size() || name.compare(0, typed.size(), typed) != 0) continue;
        if (prefix_of) return std::nullopt;  // more than one: no guess
        prefix_of = name;
    }
    return prefix_of;
}

}  // namespace bezel::cli
