// Fuzzes the pbrt scene file syntax (parseText): the input is a scene file in a scratch
// folder that also holds files to include -- one that includes another in a subfolder, one
// that includes itself, and a link that leads outside -- so Include and Import paths,
// cycles and the folder's walls are reached too.
//
// Contract checked: parseText throws only ParseError, and every directive it hands on has
// a known name, and parameters with a type, a name and values of one kind.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string_view>
#include "fuzz_support.h"
#include "import/pbrt/pbrt_parser.h"

namespace {

namespace fs = std::filesystem;

const fs::path& folder() {
    static const fs::path dir = [] {
        fs::path d = photon::fuzz::scratchDir("photon-fuzz-pbrt");
        fs::create_directories(d / "scene/sub");
        std::ofstream(d / "scene/inc.pbrt") << "AttributeBegin\nImport \"sub/b.pbrt\"\nAttributeEnd\n";
        std::ofstream(d / "scene/sub/b.pbrt") << "Shape \"sphere\" \"float radius\" 2\nInclude \"../loop.pbrt\"\n";
        std::ofstream(d / "scene/loop.pbrt") << "Include \"loop.pbrt\"\n";
        std::ofstream(d / "outside.pbrt") << "WorldBegin\n";
        fs::create_symlink(d / "outside.pbrt", d / "scene/link.pbrt");
        return d / "scene";
    }();
    return dir;
}

void checkDirective(const photon::pbrt::Directive& d) {
    if (d.name.empty() || d.where.line < 1) std::abort();
    if (d.name == "Include" || d.name == "Import") std::abort();  // inlined, never handed on
    for (const photon::pbrt::Param& p : d.params) {
        if (p.type.empty() || p.name.empty()) std::abort();
        int kinds = !p.numbers.empty() + !p.strings.empty() + !p.bools.empty();
        if (kinds > 1) std::abort();
        for (double x : p.numbers)
            if (!std::isfinite(x)) std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    photon::pbrt::ParseLimits limits;
    limits.maxFiles = 64;
    limits.maxTotalBytes = 1 << 20;
    try {
        photon::pbrt::parseText(text, "fuzz.pbrt", folder(), checkDirective, limits);
    } catch (const photon::pbrt::ParseError&) {
    }
    return 0;
}
