// FontFace: the font bytes (mapped from a file, borrowed, or shared), checked once by FreeType,
// and the state derived from them once for every user of the face.
//
// A file is mapped read-only (mmap) rather than read: a font's tables are read lazily, so a
// large CJK or emoji font costs only the pages its glyphs touch, as FreeType's and HarfBuzz's own
// file streams (which map too) did before. The mapping is shared by every Font and Shaper of the
// face and unmapped with the last of them.
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <system_error>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "bezel/font_face.hpp"
#include "bezel/limits.hpp"
#include "font/font_impl.hpp"
#include "font/ft_error.hpp"

namespace bezel {

using font_detail::ft_error_text;

struct FontFace::Impl {
    // The bytes' owner: one of the three (or none: borrowed from the caller).
    std::shared_ptr<const std::vector<std::uint8_t>> shared;
    void* mapped = nullptr;
    std::size_t mapped_size = 0;

    const std::uint8_t* data = nullptr;
    std::size_t size = 0;
    std::string name;
    bool from_file = false;
    int face_index = 0;
    int face_count = 0;
    std::uint64_t id = 0;

    std::once_flag derived_once;
    std::shared_ptr<const void> derived;   // may refer to the bytes: released before them

    Impl() = default;
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl() {
        derived.reset();
        if (mapped != nullptr) munmap(mapped, mapped_size);
    }
};

namespace {

std::uint64_t next_face_id() {
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
}

// Checks the file before mapping it, so a missing file and a directory get their own message.
Status check_regular_file(const std::string& file) {
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (status.type() == std::filesystem::file_type::not_found) {
        return Error{file + ": no such file"};
    }
    if (ec) return Error{file + ": " + ec.message()};
    if (status.type() == std::filesystem::file_type::directory) {
        return Error{file + ": is a directory, not a font file"};
    }
    if (status.type() != std::filesystem::file_type::regular) {
        return Error{file + ": not a regular file"};
    }
    return ok_status();
}

// FreeType checks the bytes: how many faces they hold (face index −1 asks only that), then that
// the face asked for opens. The probe library is dropped afterwards; each Font has its own.
// The bytes a face reads, and what FreeType found in them.
struct Bytes {
    const std::string& name;
    const std::uint8_t* data = nullptr;
    std::size_t size = 0;
    int face_index = 0;
    int face_count = 0;
};

Status check_with_freetype(Bytes& impl) {
    const std::string& name = impl.name;
    if (impl.face_index < 0 || impl.face_index > kMaxFaceIndex) {
        return Error{name + ": face index " + std::to_string(impl.face_index) +
                     " out of range (0.." + std::to_string(kMaxFaceIndex) + ")"};
    }
    FT_Library library = nullptr;
    if (FT_Error e = FT_Init_FreeType(&library)) {
        return Error{name + ": cannot start FreeType: " + ft_error_text(e)};
    }
    font_detail::LibraryPtr owner(library);
    FT_Face probe = nullptr;
    if (FT_Error e = FT_New_Memory_Face(library, impl.data, static_cast<FT_Long>(impl.size), -1,
                                        &probe)) {
        return Error{name + ": " + ft_error_text(e)};
    }
    impl.face_count = static_cast<int>(probe->num_faces);
    FT_Done_Face(probe);
    if (impl.face_index >= impl.face_count) {
        return Error{name + ": face index " + std::to_string(impl.face_index) +
                     " out of range (the file has " + std::to_string(impl.face_count) +
                     (impl.face_count == 1 ? " face)" : " faces)")};
    }
    FT_Face face = nullptr;
    if (FT_Error e = FT_New_Memory_Face(library, impl.data, static_cast<FT_Long>(impl.size),
                                        impl.face_index, &face)) {
        return Error{name + ": face " + std::to_string(impl.face_index) + ": " + ft_error_text(e)};
    }
    FT_Done_Face(face);
    return ok_status();
}

// Maps `file`; on success `mapped` is the mapping, `size` its length.
Status map_file(const std::string& file, void*& mapped, std::size_t& mapped_size) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return Error{file + ": cannot open: " + std::strerror(errno)};
    struct stat st {};
    if (fstat(fd, &st) != 0) {
        const int err = errno;
        ::close(fd);
        return Error{file + ": cannot read: " + std::strerror(err)};
    }
    const auto size = static_cast<std::size_t>(st.st_size);
    if (size == 0) {
        ::close(fd);
        return Error{file + ": empty file, not a font"};
    }
    if (size > kMaxFontBytes) {
        ::close(fd);
        return Error{file + ": " + std::to_string(size) + " bytes, larger than the " +
                     std::to_string(kMaxFontBytes) + " a font may have"};
    }
    void* p = mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    const int err = errno;
    ::close(fd);   // the mapping keeps the file
    if (p == MAP_FAILED) return Error{file + ": cannot map the file: " + std::strerror(err)};
    mapped = p;
    mapped_size = size;
    return ok_status();
}

Status check_memory(const void* data, std::size_t size, const std::string& name) {
    if (data == nullptr || size == 0) return Error{name + ": no font data (empty)"};
    if (size > kMaxFontBytes) {
        return Error{name + ": " + std::to_string(size) + " bytes, larger than the " +
                     std::to_string(kMaxFontBytes) + " a font may have"};
    }
    return ok_status();
}

}  // namespace

FontFace::FontFace(std::shared_ptr<Impl> impl) : impl_(std::move(impl)) {}

Expected<FontFace> FontFace::open(const std::string& file, int face_index) {
    if (face_index < 0 || face_index > kMaxFaceIndex) {
        return Error{file + ": face index " + std::to_string(face_index) + " out of range (0.." +
                     std::to_string(kMaxFaceIndex) + ")"};
    }
    if (Status s = check_regular_file(file); !s) return s.error();
    auto impl = std::make_shared<Impl>();
    impl->name = file;
    impl->from_file = true;
    if (Status s = map_file(file, impl->mapped, impl->mapped_size); !s) return s.error();
    Bytes bytes{impl->name, static_cast<const std::uint8_t*>(impl->mapped), impl->mapped_size,
                face_index};
    if (Status s = check_with_freetype(bytes); !s) return s.error();
    impl->data = bytes.data;
    impl->size = bytes.size;
    impl->face_index = face_index;
    impl->face_count = bytes.face_count;
    impl->id = next_face_id();
    return FontFace(std::move(impl));
}

Expected<FontFace> FontFace::from_memory(const void* data, std::size_t size,
                                         const FontMemoryOptions& options) {
    return from_memory(data, size, options, nullptr);
}

Expected<FontFace> FontFace::from_memory(std::shared_ptr<const std::vector<std::uint8_t>> bytes,
                                         const FontMemoryOptions& options) {
    const void* data = bytes ? bytes->data() : nullptr;
    const std::size_t size = bytes ? bytes->size() : 0;
    return from_memory(data, size, options, std::move(bytes));
}

Expected<FontFace> FontFace::from_memory(const void* data, std::size_t size,
                                         const FontMemoryOptions& options,
                                         std::shared_ptr<const std::vector<std::uint8_t>> owner) {
    if (Status s = check_memory(data, size, options.name); !s) return s.error();
    Bytes bytes{options.name, static_cast<const std::uint8_t*>(data), size, options.face_index};
    if (Status s = check_with_freetype(bytes); !s) return s.error();
    auto impl = std::make_shared<Impl>();
    impl->shared = std::move(owner);
    impl->name = options.name;
    impl->data = bytes.data;
    impl->size = bytes.size;
    impl->face_index = options.face_index;
    impl->face_count = bytes.face_count;
    impl->id = next_face_id();
    return FontFace(std::move(impl));
}

const std::string& FontFace::name() const { return impl_->name; }
bool FontFace::from_file() const { return impl_->from_file; }
int FontFace::face_index() const { return impl_->face_index; }
int FontFace::face_count() const { return impl_->face_count; }
const std::uint8_t* FontFace::data() const { return impl_->data; }
std::size_t FontFace::size() const { return impl_->size; }
std::uint64_t FontFace::id() const { return impl_->id; }

std::shared_ptr<const void> font_detail::derived_state(
    const FontFace& face, std::shared_ptr<const void> (*make)(const FontFace&)) {
    FontFace::Impl& impl = *face.impl_;
    std::call_once(impl.derived_once, [&] { impl.derived = make(face); });
    return impl.derived;
}

}  // namespace bezel
