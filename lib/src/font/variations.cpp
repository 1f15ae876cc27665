// Font variations: listing a variable font's axes and setting design coordinates.
//
// FreeType describes axes in FT_MM_Var (16.16 fixed-point values in the axes' user units, e.g.
// wght 100..900) and takes design coordinates in the same units.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "bezel/font.hpp"
#include "font/font_impl.hpp"
#include "font/ft_error.hpp"

#include FT_MULTIPLE_MASTERS_H

namespace bezel {

using font_detail::format_number;

namespace {

// FT_Get_MM_Var's result, freed with FT_Done_MM_Var when this goes out of scope.
struct MmVar {
    FT_Library library = nullptr;
    FT_MM_Var* var = nullptr;
    MmVar() = default;
    MmVar(const MmVar&) = delete;
    MmVar& operator=(const MmVar&) = delete;
    ~MmVar() {
        if (var != nullptr) FT_Done_MM_Var(library, var);
    }
};

// Fills `mm` for a face with variation axes; leaves it empty for any other face.
void load_mm_var(FT_Library library, FT_Face face, MmVar& mm) {
    mm.library = library;
    if (!FT_HAS_MULTIPLE_MASTERS(face)) return;
    if (FT_Get_MM_Var(face, &mm.var) != 0) mm.var = nullptr;
}

std::string tag_string(FT_ULong tag) {
    std::string s(4, ' ');
    for (int i = 0; i < 4; ++i) s[i] = static_cast<char>((tag >> (24 - 8 * i)) & 0xFF);
    return s;
}

double from_fixed(FT_Fixed v) { return static_cast<double>(v) / 65536.0; }

}  // namespace

std::vector<VariationAxis> Font::axes() const {
    MmVar mm;
    load_mm_var(impl_->library.get(), impl_->face.get(), mm);
    std::vector<VariationAxis> axes;
    if (mm.var == nullptr) return axes;
    for (FT_UInt i = 0; i < mm.var->num_axis; ++i) {
        const FT_Var_Axis& a = mm.var->axis[i];
        VariationAxis axis;
        axis.tag = tag_string(a.tag);
        axis.name = (a.name != nullptr && a.name[0] != '\0') ? a.name : axis.tag;
        axis.min_value = from_fixed(a.minimum);
        axis.default_value = from_fixed(a.def);
        axis.max_value = from_fixed(a.maximum);
        axes.push_back(std::move(axis));
    }
    return axes;
}

Status Font::set_variations(const std::vector<VariationSetting>& settings) {
    const std::string& file = impl_->file;
    MmVar mm;
    load_mm_var(impl_->library.get(), impl_->face.get(), mm);
    if (mm.var == nullptr) {
        if (settings.empty()) return ok_status();
        return Error{file + ": variation axis '" + settings.front().tag +
                     "': the font has no variation axes"};
    }
    std::vector<FT_Fixed> coords(mm.var->num_axis);
    for (FT_UInt i = 0; i < mm.var->num_axis; ++i) coords[i] = mm.var->axis[i].def;

    // Later settings of the same tag win, as in HarfBuzz's --variations.
    for (const VariationSetting& s : settings) {
        FT_UInt found = mm.var->num_axis;
        for (FT_UInt i = 0; i < mm.var->num_axis; ++i) {
            if (tag_string(mm.var->axis[i].tag) == s.tag) found = i;
        }
        if (found == mm.var->num_axis) {
            return Error{file + ": unknown variation axis '" + s.tag + "'"};
        }
        const FT_Var_Axis& a = mm.var->axis[found];
        const double lo = from_fixed(a.minimum), hi = from_fixed(a.maximum);
        if (!(s.value >= lo && s.value <= hi)) {  // also rejects NaN
            return Error{file + ": variation " + s.tag + "=" + format_number(s.value) +
                         " out of range [" + format_number(lo) + ", " + format_number(hi) + "]"};
        }
        // Rounding to 16.16 can step just outside a bound that is not a multiple of 1/65536;
        // clamp to FreeType's own fixed-point bounds.
        const FT_Fixed v = static_cast<FT_Fixed>(std::lround(s.value * 65536.0));
        coords[found] = std::min(std::max(v, a.minimum), a.maximum);
    }
    if (FT_Error e = FT_Set_Var_Design_Coordinates(impl_->face.get(), mm.var->num_axis,
                                                   coords.data())) {
        return Error{file + ": cannot set variations: " + font_detail::ft_error_text(e)};
    }
    // The instance id of these coordinates: the one they had when set lately, else a new one.
    // The last kRecentInstances are remembered: a renderer switching between a few instances
    // keeps hitting its glyph cache, and the list stays small whatever a caller animates.
    constexpr std::size_t kRecentInstances = 8;
    auto& recent = impl_->recent_instances;
    auto found = std::find_if(recent.begin(), recent.end(),
                              [&](const auto& r) { return r.first == coords; });
    if (found != recent.end()) {
        impl_->instance_id = found->second;
        std::rotate(recent.begin(), found, found + 1);   // most recent first
        return ok_status();
    }
    impl_->instance_id = font_detail::next_instance_id();
    if (recent.size() == kRecentInstances) recent.pop_back();
    recent.insert(recent.begin(), {std::move(coords), impl_->instance_id});
    return ok_status();
}

Expected<std::vector<VariationSetting>> font_detail::named_instance_coordinates(
    const std::string& file, int face_index, int instance) {
    Expected<Font> font = Font::open(file, face_index);
    if (!font) return font.error();
    auto& impl = font_detail::Access::impl(*font);
    MmVar mm;
    load_mm_var(impl.library.get(), impl.face.get(), mm);
    if (mm.var == nullptr) {
        return Error{file + ": named instance " + std::to_string(instance) +
                     ": the font has no variation axes"};
    }
    if (instance < 1 || static_cast<FT_UInt>(instance) > mm.var->num_namedstyles) {
        return Error{file + ": named instance " + std::to_string(instance) + " out of range (1.." +
                     std::to_string(mm.var->num_namedstyles) + ")"};
    }
    const FT_Var_Named_Style& style = mm.var->namedstyle[instance - 1];
    std::vector<VariationSetting> settings;
    settings.reserve(mm.var->num_axis);
    for (FT_UInt i = 0; i < mm.var->num_axis; ++i) {
        settings.push_back({tag_string(mm.var->axis[i].tag), from_fixed(style.coords[i])});
    }
    return settings;
}

}  // namespace bezel
