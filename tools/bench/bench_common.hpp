// Helpers the glyph benchmarks share (bench_raster, bench_glyph_set).
#pragma once

#include <time.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace bench {

// CPU time of this thread, not wall time: the benchmark machine is shared (others compile on
// it), and preemption would otherwise be billed to whichever renderer happened to be running.
inline double thread_ns() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

// "12,16,24" → {12, 16, 24}; entries outside 1-4096 px are dropped.
inline std::vector<int> parse_sizes(const std::string& s) {
    std::vector<int> out;
    std::size_t i = 0;
    while (i < s.size()) {
        std::size_t j = s.find(',', i);
        if (j == std::string::npos) j = s.size();
        const int v = std::atoi(s.substr(i, j - i).c_str());
        if (v > 0 && v <= 4096) out.push_back(v);
        i = j + 1;
    }
    return out;
}

}  // namespace bench
