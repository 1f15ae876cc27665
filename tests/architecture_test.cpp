// The module map is one fact: the table in docs/architecture.md (between the module-map markers)
// must equal the links CMakeLists.txt gives each module, and every #include in lib/ and tools/bezel
// must follow it — a module includes only its own headers and those of the modules it depends on
// (directly or through them), third-party headers only where the table's "sees" column allows,
// and the CLI only public headers.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace bezel {
namespace {

const fs::path kRoot = BEZEL_SOURCE_DIR;

std::string read_file(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::set<std::string> split_list(const std::string& cell) {
    std::set<std::string> out;
    std::stringstream ss(cell);
    std::string item;
    while (std::getline(ss, item, ',')) {
        item.erase(0, item.find_first_not_of(" \t`"));
        item.erase(item.find_last_not_of(" \t`") + 1);
        if (!item.empty() && item != "—" && item != "-") out.insert(item);
    }
    return out;
}

struct Module {
    std::set<std::string> deps, headers, sees;
};

// Headers every module may include (no code of their own): the table's row "(common)".
const std::string kCommon = "(common)";

// The table of docs/architecture.md: | module | depends on | public headers | sees |.
std::map<std::string, Module> documented_map() {
    const std::string doc = read_file(kRoot / "docs/architecture.md");
    const auto begin = doc.find("<!-- module-map -->"), end = doc.find("<!-- /module-map -->");
    EXPECT_NE(begin, std::string::npos) << "docs/architecture.md has no <!-- module-map --> block";
    EXPECT_NE(end, std::string::npos) << "docs/architecture.md has no <!-- /module-map --> marker";
    std::map<std::string, Module> map;
    if (begin == std::string::npos || end == std::string::npos) return map;
    std::stringstream ss(doc.substr(begin, end - begin));
    std::string line;
    while (std::getline(ss, line)) {
        if (line.rfind("| ", 0) != 0 || line.find("---") != std::string::npos) continue;
        std::vector<std::string> cells;
        std::stringstream ls(line.substr(1));
        std::string cell;
        while (std::getline(ls, cell, '|')) cells.push_back(cell);
        if (cells.size() < 4) continue;
        const auto name = split_list(cells[0]);
        if (name.size() != 1 || *name.begin() == "module") continue;
        map[*name.begin()] = {split_list(cells[1]), split_list(cells[2]), split_list(cells[3])};
    }
    return map;
}

// What CMake links: lines "module: dep dep" written at configure time (CMakeLists.txt).
std::map<std::string, std::set<std::string>> cmake_map() {
    std::map<std::string, std::set<std::string>> map;
    std::ifstream in(BEZEL_MODULE_MAP_FILE);
    std::string line;
    while (std::getline(in, line)) {
        const auto colon = line.find(':');
        if (colon == std::string::npos) continue;
        std::set<std::string>& deps = map[line.substr(0, colon)];
        std::stringstream ss(line.substr(colon + 1));
        std::string d;
        while (ss >> d) deps.insert(d);
    }
    return map;
}

std::set<std::string> closure(const std::map<std::string, Module>& map, const std::string& m) {
    std::set<std::string> seen{m};
    std::vector<std::string> todo{m};
    while (!todo.empty()) {
        const std::string cur = todo.back();
        todo.pop_back();
        auto it = map.find(cur);
        if (it == map.end()) continue;
        for (const std::string& d : it->second.deps)
            if (seen.insert(d).second) todo.push_back(d);
    }
    return seen;
}

std::vector<std::string> includes(const fs::path& file, const std::regex& pattern) {
    std::vector<std::string> out;
    std::ifstream in(file);
    std::string line;
    std::smatch m;
    while (std::getline(in, line))
        if (std::regex_search(line, m, pattern)) out.push_back(m[1]);
    return out;
}

std::vector<fs::path> sources(const fs::path& dir) {
    std::vector<fs::path> out;
    if (!fs::is_directory(dir)) return out;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string ext = e.path().extension().string();
        if (ext == ".cpp" || ext == ".hpp" || ext == ".h") out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Third-party header → the name the "sees" column uses for it.
std::string third_party(const std::string& header) {
    if (header == "ft2build.h" || header.rfind("freetype/", 0) == 0) return "FreeType";
    if (header.rfind("hb", 0) == 0 || header.rfind("harfbuzz/", 0) == 0) return "HarfBuzz";
    if (header.rfind("fribidi", 0) == 0) return "FriBidi";
    if (header.rfind("fontconfig/", 0) == 0) return "fontconfig";
    if (header.rfind("unicode/", 0) == 0) return "ICU";
    if (header == "png.h") return "libpng";
    if (header == "zlib.h") return "zlib";
    if (header.rfind("isa-l", 0) == 0 || header == "igzip_lib.h") return "ISA-L";
    return "";
}

const std::regex kBezelInclude(R"(^\s*#\s*include\s*"bezel/([^"]+)\")");
const std::regex kPrivateInclude(R"(^\s*#\s*include\s*"([a-z_0-9]+)/[^"]+")");
const std::regex kSystemInclude(R"(^\s*#\s*include\s*<([^>]+)>)");

TEST(Architecture, DocumentedModuleMapIsWhatCMakeLinks) {
    const auto doc = documented_map();
    const auto cmake = cmake_map();
    ASSERT_FALSE(cmake.empty()) << BEZEL_MODULE_MAP_FILE;
    std::set<std::string> doc_modules, cmake_modules;
    for (const auto& [m, info] : doc)
        if (m != kCommon) doc_modules.insert(m);
    for (const auto& [m, deps] : cmake) cmake_modules.insert(m);
    EXPECT_EQ(doc_modules, cmake_modules) << "modules in docs/architecture.md vs CMakeLists.txt";
    for (const auto& [m, deps] : cmake) {
        auto it = doc.find(m);
        if (it == doc.end()) continue;
        EXPECT_EQ(it->second.deps, deps) << "module " << m << ": docs/architecture.md says one set "
                                         << "of dependencies, CMakeLists.txt links another";
    }
}

TEST(Architecture, EveryPublicHeaderBelongsToOneModule) {
    const auto doc = documented_map();
    std::map<std::string, std::string> owner;
    for (const auto& [m, info] : doc)
        for (const std::string& h : info.headers) {
            EXPECT_EQ(owner.count(h), 0u) << h << " is listed under two modules";
            owner[h] = m;
        }
    for (const auto& e : fs::directory_iterator(kRoot / "lib/include/bezel")) {
        const std::string name = e.path().filename().string();
        EXPECT_EQ(owner.count(name), 1u)
            << "lib/include/bezel/" << name << " is in no module of docs/architecture.md";
    }
    for (const auto& [h, m] : owner)
        EXPECT_TRUE(fs::exists(kRoot / "lib/include/bezel" / h))
            << "docs/architecture.md lists " << h << " under " << m << ", which does not exist";
}

// libbezel.so exports what the public headers declare and nothing else (CMakeLists.txt): each
// header that declares anything wraps its declarations, after its #includes, in default
// visibility over a library compiled with -fvisibility=hidden. A header without the pair would
// compile and link statically, and be missing from the shared library.
TEST(Architecture, EveryPublicHeaderExportsItsDeclarations) {
    const std::regex push(R"(\n#pragma GCC visibility push\(default\)[^\n]*\nnamespace bezel)");
    const std::string pop = "\n#pragma GCC visibility pop\n";
    for (const auto& e : fs::directory_iterator(kRoot / "lib/include/bezel")) {
        const std::string text = read_file(e.path());
        const std::string name = e.path().filename().string();
        if (text.find("namespace bezel") == std::string::npos) continue;  // an umbrella header
        std::smatch m;
        ASSERT_TRUE(std::regex_search(text, m, push))
            << name << ": no `#pragma GCC visibility push(default)` right before namespace bezel";
        EXPECT_EQ(text.find("#include", static_cast<std::size_t>(m.position(0))), std::string::npos)
            << name << ": an #include inside the exported region";
        EXPECT_EQ(text.size() >= pop.size() ? text.substr(text.size() - pop.size()) : "", pop)
            << name << ": does not end with `#pragma GCC visibility pop`";
    }
}

TEST(Architecture, LibraryIncludesFollowTheModuleMap) {
    const auto doc = documented_map();
    std::map<std::string, std::string> owner;
    for (const auto& [m, info] : doc)
        for (const std::string& h : info.headers) owner[h] = m;
    for (const auto& [m, info] : doc) {
        std::set<std::string> allowed = closure(doc, m);
        allowed.insert(kCommon);
        std::vector<fs::path> files = sources(kRoot / "lib/src" / m);
        for (const std::string& h : info.headers) files.push_back(kRoot / "lib/include/bezel" / h);
        for (const fs::path& f : files) {
            const std::string where = fs::relative(f, kRoot).string();
            const bool public_header = where.rfind("lib/include/", 0) == 0;
            for (const std::string& h : includes(f, kBezelInclude)) {
                auto o = owner.find(h);
                if (o == owner.end()) continue;  // reported by EveryPublicHeaderBelongsToOneModule
                EXPECT_TRUE(allowed.count(o->second))
                    << where << " (module " << m << ") includes bezel/" << h << " of module "
                    << o->second << ", which " << m << " does not depend on";
            }
            for (const std::string& dir : includes(f, kPrivateInclude)) {
                if (fs::is_directory(kRoot / "lib/src" / dir)) {
                    EXPECT_TRUE(dir == m && !public_header)
                        << where << " includes a private header of module " << dir;
                }
            }
            for (const std::string& h : includes(f, kSystemInclude)) {
                const std::string lib = third_party(h);
                if (lib.empty()) continue;
                EXPECT_TRUE(!public_header && info.sees.count(lib))
                    << where << " includes <" << h << "> (" << lib << "), which module " << m
                    << (public_header ? "'s public headers must not" : " does not see");
            }
        }
    }
}

TEST(Architecture, CliUsesThePublicLibraryOnly) {
    for (const fs::path& f : sources(kRoot / "tools/bezel")) {
        const std::string where = fs::relative(f, kRoot).string();
        for (const std::string& dir : includes(f, kPrivateInclude)) {
            EXPECT_FALSE(fs::is_directory(kRoot / "lib/src" / dir))
                << where << " includes a private header of module " << dir;
        }
        for (const std::string& h : includes(f, kSystemInclude))
            EXPECT_EQ(third_party(h), "") << where << " includes <" << h << ">";
    }
}

// integrations/ (bezel_imgui and its example) and python/src (the pybind11 extension) are
// consumers: public headers only, and none of the third-party libraries bezel hides (they may
// include their own toolkit's headers: Dear ImGui's, pybind11's).
TEST(Architecture, IntegrationsAndPythonUseThePublicLibraryOnly) {
    for (const char* dir : {"integrations", "python/src"}) {
        int files = 0;
        for (const auto& e : fs::recursive_directory_iterator(kRoot / dir)) {
            const std::string ext = e.path().extension().string();
            if (ext != ".cpp" && ext != ".hpp") continue;
            ++files;
            const std::string where = fs::relative(e.path(), kRoot).string();
            for (const std::string& d : includes(e.path(), kPrivateInclude)) {
                EXPECT_FALSE(fs::is_directory(kRoot / "lib/src" / d))
                    << where << " includes a private header of module " << d;
            }
            for (const std::string& h : includes(e.path(), kSystemInclude))
                EXPECT_EQ(third_party(h), "") << where << " includes <" << h << ">";
        }
        EXPECT_GT(files, 0) << dir;
    }
}

}  // namespace
}  // namespace bezel
