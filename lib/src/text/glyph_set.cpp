// GlyphRasterizer::prepare_set and draw_set: a toolkit's set of glyphs through one
// Rasterizer::fill_paths call (glyph.hpp states the contract).
//
// draw_set places each outline glyph exactly as draw() does (the same transform into the same
// corner of its target, the same FillOptions with the glyph's overlap mode), so the set call's
// bytes are draw()'s; it gathers consecutive outline glyphs whose fill options agree into one
// run of FillJobs, which the Rasterizer fills with the options dispatched once.
#include <string>

#include "bezel/glyph.hpp"
#include "text/glyph_draw.hpp"

namespace bezel {

namespace {

std::string set_label(std::size_t k, GlyphId gid) {
    return "glyph set job " + std::to_string(k) + " (glyph " + std::to_string(gid) + "): ";
}

// Whether two fills make the same bytes from the same job: every field but the origin (a job's
// own).
bool same_fill(const FillOptions& a, const FillOptions& b) {
    return a.rule == b.rule && a.overlap == b.overlap &&
           a.flatten.tolerance_px == b.flatten.tolerance_px &&
           a.flatten.method == b.flatten.method &&
           a.flatten.classic_flatness_epsilon == b.flatten.classic_flatness_epsilon &&
           a.format == b.format && a.lcd_order == b.lcd_order &&
           a.lcd_filter.taps == b.lcd_filter.taps && a.combine == b.combine;
}

bool drawn_by_fill(const PreparedGlyph& glyph) {
    return glyph.box.width > 0 && glyph.box.height > 0 && !glyph.box.color && !glyph.strike;
}

}  // namespace

Status GlyphRasterizer::prepare_set(const GlyphId* gids, std::size_t count,
                                    const GlyphRenderOptions& options,
                                    std::vector<PreparedGlyph>& out) {
    out.clear();
    if (count > 0 && gids == nullptr)
        return Error{"prepare_set: the glyph id array is null with " + std::to_string(count) +
                     " glyphs"};
    out.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        auto glyph = prepare(gids[k], options);
        if (!glyph) return Error{"prepare_set: job " + std::to_string(k) + ": " + glyph.error().message};
        out.push_back(std::move(*glyph));
    }
    return ok_status();
}

Status GlyphRasterizer::draw_set(const GlyphDrawJob* jobs, std::size_t count) {
    if (count > 0 && jobs == nullptr)
        return Error{"draw_set: the job array is null with " + std::to_string(count) + " jobs"};
    // draw()'s own checks, for every job before anything is drawn.
    for (std::size_t k = 0; k < count; ++k) {
        const PreparedGlyph* glyph = jobs[k].glyph;
        if (glyph == nullptr)
            return Error{"glyph set job " + std::to_string(k) + ": the glyph is null"};
        if (glyph->box.width == 0 || glyph->box.height == 0) continue;
        if (Status s = text_detail::check_glyph_target(*glyph, jobs[k].target); !s)
            return Error{set_label(k, glyph->gid) + s.error().message};
    }

    // The run of outline glyphs gathered so far, all with the options `run_fill`.
    set_jobs_.clear();
    set_index_.clear();
    FillOptions run_fill;
    const auto flush = [&]() -> Status {
        if (set_jobs_.empty()) return ok_status();
        std::size_t failed = 0;
        Status filled = raster_.fill_paths(set_jobs_, run_fill, &failed);
        set_jobs_.clear();
        if (!filled) {
            // fill_paths names its own job index; the set's index and the glyph replace it.
            const std::size_t k = failed < set_index_.size() ? set_index_[failed] : 0;
            const std::string& m = filled.error().message;
            const std::size_t cut = m.find(": ", m.find("job "));
            return Error{set_label(k, jobs[k].glyph->gid) +
                         (cut == std::string::npos ? m : m.substr(cut + 2))};
        }
        set_index_.clear();
        return ok_status();
    };
    for (std::size_t k = 0; k < count; ++k) {
        const PreparedGlyph& glyph = *jobs[k].glyph;
        if (glyph.box.width == 0 || glyph.box.height == 0) continue;  // draw() writes nothing
        if (!drawn_by_fill(glyph)) {
            if (Status s = flush(); !s) return s;
            if (Status s = draw(glyph, jobs[k].target); !s)
                return Error{"glyph set job " + std::to_string(k) + ": " + s.error().message};
            continue;
        }
        const FillOptions fill = text_detail::outline_fill(glyph);
        if (!set_jobs_.empty() && !same_fill(fill, run_fill)) {
            if (Status s = flush(); !s) return s;
        }
        run_fill = fill;
        const FillJob job = text_detail::outline_job(glyph, jobs[k].target);
        set_jobs_.push_back(job);
        set_index_.push_back(k);
    }
    return flush();
}

}  // namespace bezel
