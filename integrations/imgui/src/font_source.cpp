#include "font_source.hpp"

#include <sys/mman.h>
#include <unistd.h>

namespace bezel_imgui::detail {

// bezel's Font opens files only: the bytes become an anonymous in-memory file (memfd), opened
// through its /proc/self/fd path. FreeType opens that path itself, so the memory file lives as
// long as the Font; the descriptor made here is closed before returning.
bezel::Expected<bezel::Font> open_font_bytes(const void* data, std::size_t size, int face_index,
                                             const std::string& name) {
    if (data == nullptr || size == 0) return bezel::Error{name + ": no font data"};
    const int fd = memfd_create("bezel_imgui_font", MFD_CLOEXEC);
    if (fd < 0) return bezel::Error{name + ": cannot make an in-memory file for the font data"};
    const auto* p = static_cast<const char*>(data);
    std::size_t left = size;
    while (left > 0) {
        const ssize_t n = write(fd, p, left);
        if (n <= 0) {
            close(fd);
            return bezel::Error{name + ": cannot copy the font data into an in-memory file"};
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    const std::string path = "/proc/self/fd/" + std::to_string(fd);
    auto font = bezel::Font::open(path, face_index);
    close(fd);
    if (!font) {
        std::string msg = font.error().message;
        if (msg.rfind(path, 0) == 0) msg.replace(0, path.size(), name);
        return bezel::Error{msg};
    }
    return font;
}

}  // namespace bezel_imgui::detail
