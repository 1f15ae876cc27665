// bezel_imgui_example — Dear ImGui on SDL2 (the SDL renderer backend) with its font atlas built
// by bezel: text at 13, 16 and 24 px, a CJK font merged into the 16 px font, and an SVG icon
// drawn by bezel into the atlas.
//
//   bezel_imgui_example [--frames N --screenshot FILE.png] [--cjk-font FILE]
//                       [--hinting none|light|full|auto]      (default full, as imgui_freetype)
//
// Interactive by default (close the window to quit). With --frames, renders N frames, saves the
// last one (SDL_RenderReadPixels) to FILE.png, prints each text item's rectangle
// ("item NAME X0 Y0 X1 Y1", window pixels) on stdout and exits: what the test runs under Xvfb.
// Exit 1 on a runtime error (SDL, the atlas build, writing the file), 2 on bad arguments.
#include <SDL.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>

#include "bezel/image.hpp"
#include "bezel_imgui.hpp"

namespace {

constexpr int kWidth = 960, kHeight = 540;
constexpr ImWchar kIconCodepoint = 0xE000;   // Private Use Area: the icon's glyph
// The icon, in a 24-unit view box: a ring and, inside it, a wave of two cubics (even-odd).
constexpr const char* kIconPath =
    "M12 1a11 11 0 1 0 0.001 0z M12 3.5a8.5 8.5 0 1 1 -0.001 0z "
    "M5 13C8 5 10 5 12 12S16 19 19 11L19 14C16 21 13 21 11.5 14S8 9 5 16z";
constexpr const char* kCjkText = "日本語のテキスト、漢字とカタカナ。한국어 안녕하세요";

struct Args {
    int frames = 0;   // 0: interactive
    std::string screenshot;
    std::string cjk_font;
    unsigned flags = 0;   // bezel_imgui::BuilderFlags
};

int usage(const std::string& why) {
    std::fprintf(stderr,
                 "bezel_imgui_example: %s\nusage: bezel_imgui_example [--frames N --screenshot "
                 "FILE.png] [--cjk-font FILE] [--hinting none|light|full|auto]\n",
                 why.c_str());
    return 2;
}

bool file_exists(const std::string& f) {
    if (FILE* fp = std::fopen(f.c_str(), "rb")) {
        std::fclose(fp);
        return true;
    }
    return false;
}

// Noto Sans CJK from Debian's fonts-noto-cjk when installed, else the repository's subset.
std::string default_cjk_font() {
    const std::string system = "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc";
    if (file_exists(system)) return system;
    return std::string(BEZEL_FONTS_DIR) + "/noto-cjk/NotoSansCJKjp-Subset.otf";
}

struct Fonts {
    ImFont* small = nullptr;   // 13 px
    ImFont* body = nullptr;    // 16 px, with CJK merged and the icon
    ImFont* large = nullptr;   // 24 px, with the icon
    std::vector<bezel_imgui::SvgIcon> icons;
};

// Adds the fonts, builds the atlas with bezel and draws the icons into it.
bool build_fonts(ImFontAtlas& atlas, const Args& args, Fonts& fonts,
                 ImVector<ImWchar>& cjk_ranges) {
    const std::string& cjk_font = args.cjk_font;
    const std::string latin = std::string(BEZEL_FONTS_DIR) + "/dejavu-sans/DejaVuSans.ttf";
    fonts.small = atlas.AddFontFromFileTTF(latin.c_str(), 13.0f);
    fonts.body = atlas.AddFontFromFileTTF(latin.c_str(), 16.0f);
    ImFontGlyphRangesBuilder ranges;
    ranges.AddText(kCjkText);
    ranges.BuildRanges(&cjk_ranges);
    ImFontConfig merge;
    merge.MergeMode = true;
    merge.OversampleH = 1;   // ideographs are dense: horizontal oversampling buys little
    const bool cjk = atlas.AddFontFromFileTTF(cjk_font.c_str(), 16.0f, &merge, cjk_ranges.Data);
    fonts.large = atlas.AddFontFromFileTTF(latin.c_str(), 24.0f);
    if (!fonts.small || !fonts.body || !fonts.large || !cjk) {
        std::fprintf(stderr, "bezel_imgui_example: cannot read %s or %s\n", latin.c_str(),
                     cjk_font.c_str());
        return false;
    }
    for (auto [font, size] : {std::pair{fonts.body, 16}, std::pair{fonts.large, 24}}) {
        bezel_imgui::SvgIconOptions o;
        o.size_px = size;
        o.offset = ImVec2(0, static_cast<float>(size) * 0.1f);
        o.rule = bezel::FillRule::EvenOdd;
        auto icon = bezel_imgui::add_svg_icon(atlas, font, kIconCodepoint, kIconPath, o);
        if (!icon) {
            std::fprintf(stderr, "bezel_imgui_example: %s\n", icon.error().message.c_str());
            return false;
        }
        fonts.icons.push_back(std::move(*icon));
    }
    atlas.FontBuilderFlags = args.flags;
    atlas.FontBuilderIO = bezel_imgui::builder();
    if (!atlas.Build()) {
        std::fprintf(stderr, "bezel_imgui_example: font atlas: %s\n",
                     bezel_imgui::last_build_error().c_str());
        return false;
    }
    for (const auto& icon : fonts.icons) {
        if (auto drawn = bezel_imgui::draw_svg_icon(atlas, icon); !drawn) {
            std::fprintf(stderr, "bezel_imgui_example: %s\n", drawn.error().message.c_str());
            return false;
        }
    }
    return true;
}

struct Item {
    std::string name;
    ImVec2 min, max;
};

void text_item(std::vector<Item>& items, const char* name, ImFont* font, const char* text) {
    ImGui::PushFont(font);
    ImGui::TextUnformatted(text);
    ImGui::PopFont();
    items.push_back({name, ImGui::GetItemRectMin(), ImGui::GetItemRectMax()});
}

// One frame's content: a borderless window over the whole screen, text only, the lower part of
// the screen left empty (the test checks it stays background).
void draw_ui(const Fonts& fonts, std::vector<Item>& items) {
    items.clear();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(kWidth, kHeight));
    ImGui::Begin("bezel", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                                       ImGuiWindowFlags_NoSavedSettings);
    text_item(items, "small", fonts.small, "13 px: Dear ImGui text rasterized by bezel (DejaVu Sans).");
    text_item(items, "body", fonts.body, "16 px: The quick brown fox jumps over the lazy dog. 0123456789");
    text_item(items, "latin1", fonts.body, "Latin-1: àéîõü ÀÉÎÕÜ ßæøå ¿¡ «»");
    text_item(items, "cjk", fonts.body, kCjkText);
    text_item(items, "large", fonts.large, "24 px: Sphinx of black quartz, judge my vow.");
    text_item(items, "icon", fonts.large, "\xEE\x80\x80 an SVG icon drawn by bezel \xEE\x80\x80");
    text_item(items, "icon_body", fonts.body, "\xEE\x80\x80 the icon at 16 px");
    ImGui::End();
}

bool save_screenshot(SDL_Renderer* renderer, const std::string& file) {
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(kWidth) * kHeight * 4);
    if (SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_RGBA32, pixels.data(),
                             kWidth * 4) != 0) {
        std::fprintf(stderr, "bezel_imgui_example: SDL_RenderReadPixels: %s\n", SDL_GetError());
        return false;
    }
    bezel::Image image(kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::uint8_t* p = &pixels[(static_cast<std::size_t>(y) * kWidth + x) * 4];
            image.at(x, y) = bezel::Rgba8{p[0], p[1], p[2], 255};
        }
    if (auto written = bezel::write_png(file, image, bezel::PngColor::Rgb); !written) {
        std::fprintf(stderr, "bezel_imgui_example: %s\n", written.error().message.c_str());
        return false;
    }
    return true;
}

bool parse_args(int argc, char** argv, Args& args, std::string& why) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc) {
            why = "option " + a + " needs a value";
            return false;
        }
        const std::string v = argv[++i];
        if (a == "--frames") {
            char* end = nullptr;
            const long n = std::strtol(v.c_str(), &end, 10);
            if (end == v.c_str() || *end != '\0' || n < 1 || n > 100000) {
                why = "--frames: '" + v + "' is not a frame count 1..100000";
                return false;
            }
            args.frames = static_cast<int>(n);
        } else if (a == "--screenshot") {
            args.screenshot = v;
        } else if (a == "--cjk-font") {
            args.cjk_font = v;
        } else if (a == "--hinting") {
            if (v == "none") args.flags = bezel_imgui::NoHinting;
            else if (v == "light") args.flags = bezel_imgui::LightHinting;
            else if (v == "full") args.flags = 0;
            else if (v == "auto") args.flags = bezel_imgui::ForceAutoHint;
            else {
                why = "--hinting: '" + v + "' is not none, light, full or auto";
                return false;
            }
        } else {
            why = "unknown option '" + a + "'";
            return false;
        }
    }
    if ((args.frames > 0) != !args.screenshot.empty()) {
        why = "--frames and --screenshot go together";
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    Args args;
    std::string why;
    if (!parse_args(argc, argv, args, why)) return usage(why);
    if (args.cjk_font.empty()) args.cjk_font = default_cjk_font();

    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        std::fprintf(stderr, "bezel_imgui_example: SDL_Init: %s\n", SDL_GetError());
        return 1;
    }
    SDL_Window* window = SDL_CreateWindow("bezel + Dear ImGui", SDL_WINDOWPOS_CENTERED,
                                          SDL_WINDOWPOS_CENTERED, kWidth, kHeight, 0);
    SDL_Renderer* renderer = window ? SDL_CreateRenderer(window, -1, 0) : nullptr;
    if (!renderer) {
        std::fprintf(stderr, "bezel_imgui_example: SDL window or renderer: %s\n", SDL_GetError());
        if (window) SDL_DestroyWindow(window);
        SDL_Quit();
        return 1;
    }

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    Fonts fonts;
    ImVector<ImWchar> cjk_ranges;   // must outlive the atlas build
    int status = 0;
    if (!build_fonts(*io.Fonts, args, fonts, cjk_ranges)) {
        status = 1;
    } else {
        ImGui_ImplSDL2_InitForSDLRenderer(window);
        ImGui_ImplSDLRenderer_Init(renderer);
        std::vector<Item> items;
        bool running = true;
        for (int frame = 1; running; ++frame) {
            SDL_Event event;
            while (SDL_PollEvent(&event)) {
                ImGui_ImplSDL2_ProcessEvent(&event);
                if (event.type == SDL_QUIT) running = false;
            }
            ImGui_ImplSDLRenderer_NewFrame();
            ImGui_ImplSDL2_NewFrame();
            ImGui::NewFrame();
            draw_ui(fonts, items);
            ImGui::Render();
            SDL_SetRenderDrawColor(renderer, 30, 32, 40, 255);
            SDL_RenderClear(renderer);
            ImGui_ImplSDLRenderer_RenderDrawData(ImGui::GetDrawData());
            if (args.frames > 0 && frame == args.frames) {
                if (!save_screenshot(renderer, args.screenshot)) status = 1;
                for (const Item& it : items)
                    std::printf("item %s %.0f %.0f %.0f %.0f\n", it.name.c_str(), it.min.x,
                                it.min.y, it.max.x, it.max.y);
                running = false;
            }
            SDL_RenderPresent(renderer);
        }
        ImGui_ImplSDLRenderer_Shutdown();
        ImGui_ImplSDL2_Shutdown();
    }
    ImGui::DestroyContext();
    SDL_DestroyRenderer(renderer);
    SDL_DestroyWindow(window);
    SDL_Quit();
    return status;
}
