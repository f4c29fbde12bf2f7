// The pbrt scene file syntax: tokens with their lines, every directive's positional values
// and parameters, Include/Import inlined inside the scene's folder, each error's exact
// file:line message, and excerpts of real pbrt-v4 scenes (Bitterli's, CC0).
#include <gtest/gtest.h>

#include <fstream>
#include <unistd.h>

#include "import/pbrt/pbrt_parser.h"
#include "pbrt_bitterli_scenes.h"
#include "test_support.h"

namespace photon::pbrt {
namespace {

namespace fs = std::filesystem;

std::vector<Directive> parse(std::string_view text, const fs::path& root = fs::temp_directory_path()) {
    std::vector<Directive> out;
    parseText(text, "scene.pbrt", root, [&](Directive&& d) { out.push_back(std::move(d)); });
    return out;
}

// The what() of the ParseError that parsing `text` throws ("" if none).
std::string errorOf(std::string_view text) {
    try {
        parse(text);
    } catch (const ParseError& e) {
        return e.what();
    }
    return "";
}

std::vector<Token> tokens(std::string_view text) {
    Tokenizer tokenizer(text, "t.pbrt");
    std::vector<Token> out;
    for (Token t = tokenizer.next(); t.kind != TokenKind::End; t = tokenizer.next()) out.push_back(t);
    return out;
}

TEST(PbrtTokenizer, CutsWordsStringsNumbersAndBracketsWithTheirLines) {
    auto t = tokens("Shape \"sphere\"\n  \"float radius\" [-.5e-3 +2 7 1e10]\nWorldBegin");
    ASSERT_EQ(t.size(), 10u);
    EXPECT_EQ(t[0].kind, TokenKind::Word);
    EXPECT_EQ(t[0].text, "Shape");
    EXPECT_EQ(t[1].kind, TokenKind::String);
    EXPECT_EQ(t[1].text, "sphere");
    EXPECT_EQ(t[1].line, 1);
    EXPECT_EQ(t[2].text, "float radius");
    EXPECT_EQ(t[2].line, 2);
    EXPECT_EQ(t[3].kind, TokenKind::OpenBracket);
    EXPECT_EQ(t[4].kind, TokenKind::Number);
    EXPECT_DOUBLE_EQ(t[4].number, -0.5e-3);
    EXPECT_DOUBLE_EQ(t[5].number, 2);
    EXPECT_DOUBLE_EQ(t[6].number, 7);
    EXPECT_DOUBLE_EQ(t[7].number, 1e10);
    EXPECT_EQ(t[8].kind, TokenKind::CloseBracket);
    EXPECT_EQ(t[9].text, "WorldBegin");
    EXPECT_EQ(t[9].line, 3);
}

TEST(PbrtTokenizer, SkipsCommentsAndOddWhitespace) {
    auto t = tokens("# header\r\n\tAttributeBegin # trailing \"not a string\"\r\n\f\v[1]# no newline at the end");
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[0].text, "AttributeBegin");
    EXPECT_EQ(t[0].line, 2);
    EXPECT_EQ(t[1].kind, TokenKind::OpenBracket);
    EXPECT_EQ(t[1].line, 3);
    EXPECT_DOUBLE_EQ(t[2].number, 1);
    EXPECT_TRUE(tokens("   \n# only a comment").empty());
}

TEST(PbrtTokenizer, UnescapesStrings) {
    auto t = tokens(R"("a \"quoted\" \\ path\n\tend" "plain")");
    ASSERT_EQ(t.size(), 2u);
    EXPECT_TRUE(t[0].escaped);
    EXPECT_EQ(unescape(t[0]), "a \"quoted\" \\ path\n\tend");
    EXPECT_FALSE(t[1].escaped);
    EXPECT_EQ(unescape(t[1]), "plain");
}

TEST(PbrtTokenizer, TinyNumbersRoundToZeroButHugeOnesAreErrors) {
    EXPECT_DOUBLE_EQ(tokens("1e-400")[0].number, 0.0);
    EXPECT_THROW(tokens("1e400"), ParseError);
}

TEST(PbrtParser, DirectivesWithoutArguments) {
    auto d = parse("AttributeBegin AttributeEnd WorldBegin WorldEnd ObjectEnd ReverseOrientation\n"
                   "TransformBegin TransformEnd Identity");
    std::vector<std::string> names;
    for (const Directive& x : d) {
        names.push_back(x.name);
        EXPECT_TRUE(x.numbers.empty() && x.strings.empty() && x.params.empty());
    }
    EXPECT_EQ(names, (std::vector<std::string>{"AttributeBegin", "AttributeEnd", "WorldBegin", "WorldEnd", "ObjectEnd",
                                               "ReverseOrientation", "TransformBegin", "TransformEnd", "Identity"}));
    EXPECT_EQ(d[8].where.str(), "scene.pbrt:2");
}

TEST(PbrtParser, TransformDirectivesTakeTheirNumbers) {
    auto d = parse("LookAt 0 1 2  3 4 5\n 0 1 0\nTranslate 1 -2 3.5\nScale 2 2 2\nRotate 90 0 0 1\n"
                   "Transform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1]\nConcatTransform 2 0 0 0 0 2 0 0 0 0 2 0 1 2 3 1\n"
                   "TransformTimes 0 1");
    ASSERT_EQ(d.size(), 7u);
    EXPECT_EQ(d[0].name, "LookAt");
    EXPECT_EQ(d[0].numbers, (std::vector<double>{0, 1, 2, 3, 4, 5, 0, 1, 0}));
    EXPECT_EQ(d[1].numbers, (std::vector<double>{1, -2, 3.5}));
    EXPECT_EQ(d[1].where.line, 3);
    EXPECT_EQ(d[2].numbers, (std::vector<double>{2, 2, 2}));
    EXPECT_EQ(d[3].numbers, (std::vector<double>{90, 0, 0, 1}));
    ASSERT_EQ(d[4].numbers.size(), 16u);
    EXPECT_EQ(d[4].numbers[15], 1);
    ASSERT_EQ(d[5].numbers.size(), 16u);
    EXPECT_EQ(d[5].numbers[13], 2);
    EXPECT_EQ(d[6].numbers, (std::vector<double>{0, 1}));
}

TEST(PbrtParser, DirectivesNamingThings) {
    auto d = parse("NamedMaterial \"red\" ObjectBegin \"tree\" ObjectInstance \"tree\" CoordinateSystem \"cam\"\n"
                   "CoordSysTransform \"camera\" ColorSpace \"aces2065-1\" ActiveTransform StartTime\n"
                   "MediumInterface \"fog\" MediumInterface \"\" \"smoke\"");
    ASSERT_EQ(d.size(), 9u);
    const char* names[] = {"NamedMaterial", "ObjectBegin", "ObjectInstance", "CoordinateSystem", "CoordSysTransform",
                           "ColorSpace", "ActiveTransform", "MediumInterface", "MediumInterface"};
    const std::vector<std::string> strings[] = {{"red"}, {"tree"}, {"tree"}, {"cam"}, {"camera"}, {"aces2065-1"},
                                                {"StartTime"}, {"fog"}, {"", "smoke"}};
    for (size_t i = 0; i < d.size(); ++i) {
        EXPECT_EQ(d[i].name, names[i]);
        EXPECT_EQ(d[i].strings, strings[i]) << names[i];
    }
}

TEST(PbrtParser, DirectivesWithParameters) {
    auto d = parse("Camera \"perspective\" \"float fov\" [ 45 ]\n"
                   "Film \"rgb\" \"string filename\" \"out.exr\" \"integer xresolution\" 640\n"
                   "Sampler \"halton\" Integrator \"volpath\" PixelFilter \"gaussian\" Accelerator \"bvh\"\n"
                   "Material \"diffuse\" \"texture reflectance\" \"wood\"\n"
                   "LightSource \"point\" \"blackbody I\" [ 5500 ] \"point3 from\" [0 4 0]\n"
                   "AreaLightSource \"diffuse\" \"rgb L\" [17 12 4]\n"
                   "MakeNamedMaterial \"gold\" \"string type\" \"conductor\" \"spectrum eta\" \"metal-Au-eta\"\n"
                   "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"spectrum sigma_a\" [200 0.1 900 0.2]\n"
                   "Attribute \"shape\" \"float radius\" 0.5\n"
                   "Texture \"wood\" \"spectrum\" \"imagemap\" \"string filename\" \"wood.png\"\n"
                   "Option \"bool disablepixeljitter\" true\n"
                   "Shape \"sphere\"");
    ASSERT_EQ(d.size(), 15u);
    EXPECT_EQ(d[0].strings, std::vector<std::string>{"perspective"});
    ASSERT_EQ(d[0].params.size(), 1u);
    const Param& fov = d[0].params[0];
    EXPECT_EQ(fov.type, "float");
    EXPECT_EQ(fov.name, "fov");
    EXPECT_EQ(fov.numbers, std::vector<double>{45});
    EXPECT_EQ(fov.where.str(), "scene.pbrt:1");
    ASSERT_NE(d[1].find("filename"), nullptr);
    EXPECT_EQ(d[1].find("filename")->strings, std::vector<std::string>{"out.exr"});
    EXPECT_EQ(d[1].find("xresolution")->numbers, std::vector<double>{640});
    EXPECT_EQ(d[1].find("yresolution"), nullptr);
    EXPECT_EQ(d[2].name, "Sampler");
    EXPECT_EQ(d[5].strings, std::vector<std::string>{"bvh"});
    EXPECT_EQ(d[6].find("reflectance")->type, "texture");
    EXPECT_EQ(d[6].find("reflectance")->strings, std::vector<std::string>{"wood"});
    EXPECT_EQ(d[7].find("I")->numbers, std::vector<double>{5500});
    EXPECT_EQ(d[7].find("from")->type, "point3");
    EXPECT_EQ(d[8].find("L")->numbers, (std::vector<double>{17, 12, 4}));
    EXPECT_EQ(d[9].find("eta")->strings, std::vector<std::string>{"metal-Au-eta"});
    EXPECT_TRUE(d[9].find("eta")->numbers.empty());
    EXPECT_EQ(d[10].find("sigma_a")->numbers, (std::vector<double>{200, 0.1, 900, 0.2}));
    EXPECT_EQ(d[11].strings, std::vector<std::string>{"shape"});
    EXPECT_EQ(d[12].strings, (std::vector<std::string>{"wood", "spectrum", "imagemap"}));
    EXPECT_EQ(d[12].params.size(), 1u);
    EXPECT_TRUE(d[13].strings.empty());
    EXPECT_EQ(d[13].find("disablepixeljitter")->bools, std::vector<bool>{true});
    EXPECT_EQ(d[14].strings, std::vector<std::string>{"sphere"});
    EXPECT_TRUE(d[14].params.empty());
}

TEST(PbrtParser, BoolsBareOrQuotedAndOtherValueForms) {
    auto d = parse("Shape \"x\" \"bool a\" [ false ] \"bool b\" \"true\" \"bool c\" [\"false\" true]\n"
                   "  \"  integer   indices  \" [0 1 2] \"float empty\" [ ] \"string s\" [\"a\" \"b\"]");
    ASSERT_EQ(d.size(), 1u);
    const Directive& s = d[0];
    EXPECT_EQ(s.find("a")->bools, std::vector<bool>{false});
    EXPECT_TRUE(s.find("a")->numbers.empty());
    EXPECT_EQ(s.find("b")->bools, std::vector<bool>{true});
    EXPECT_EQ(s.find("c")->bools, (std::vector<bool>{false, true}));
    EXPECT_EQ(s.find("indices")->type, "integer");
    EXPECT_EQ(s.find("indices")->numbers, (std::vector<double>{0, 1, 2}));
    EXPECT_EQ(s.find("indices")->where.line, 2);
    EXPECT_TRUE(s.find("empty")->numbers.empty());
    EXPECT_EQ(s.find("s")->strings, (std::vector<std::string>{"a", "b"}));
}

TEST(PbrtParser, ErrorsNameTheirFileAndLine) {
    const std::pair<const char*, const char*> cases[] = {
        {"Shape \"sphere\"\n\n\"float radius [2]", "scene.pbrt:3: unterminated string"},
        {"Shape \"sphere\" \"float radius\" [ 1\n\nWorldBegin", "scene.pbrt:1: unbalanced '[': parameter \"float radius\" has no ']' before WorldBegin on line 3"},
        {"Shape \"sphere\" \"float radius\" [ 1\n2\n", "scene.pbrt:1: unbalanced '[': parameter \"float radius\" has no ']'"},
        {"WorldBegin\n]", "scene.pbrt:2: unbalanced ']'"},
        {"Camera \"perspective\"\n \"float fov\"\nWorldBegin", "scene.pbrt:2: parameter \"float fov\" has no value"},
        {"Camera \"perspective\"\n \"float fov\"", "scene.pbrt:2: parameter \"float fov\" has no value"},
        {"Camera \"perspective\" \"float fov\"\n[ \"wide\" ]", "scene.pbrt:2: parameter \"float fov\" expects numbers, found string \"wide\""},
        {"Film \"rgb\" \"string filename\" 3", "scene.pbrt:1: parameter \"string filename\" expects strings, found number 3"},
        {"Shape \"x\" \"float r\" [1 true]", "scene.pbrt:1: parameter \"float r\" expects numbers, found bare word 'true'"},
        {"Shape \"x\" \"float r\" [1 [2]]", "scene.pbrt:1: '[' inside the values of parameter \"float r\""},
        {"Shape \"x\" \"bool b\" 1", "scene.pbrt:1: parameter \"bool b\" expects true or false, found number 1"},
        {"Shape \"x\" \"bool b\" \"yes\"", "scene.pbrt:1: parameter \"bool b\" expects true or false, found string \"yes\""},
        {"Shape \"x\" \"integer indices\" [0 1.5]", "scene.pbrt:1: parameter \"integer indices\" expects integers, found number 1.5"},
        {"Shape \"x\" \"spectrum eta\" [300 \"a\"]", "scene.pbrt:1: parameter \"spectrum eta\" mixes numbers and strings"},
        {"Shape \"x\" \"float\" 1", "scene.pbrt:1: expected a parameter declaration \"type name\", found string \"float\""},
        {"Shape \"x\" \"float a b\" 1", "scene.pbrt:1: expected a parameter declaration \"type name\", found string \"float a b\""},
        {"Shape \"x\" \"flaot r\" 1", "scene.pbrt:1: unknown parameter type 'flaot' in \"flaot r\""},
        {"WorldBegin\nSphere \"x\"", "scene.pbrt:2: unknown directive 'Sphere'"},
        {"WorldBegin\n\"float x\" 1", "scene.pbrt:2: expected a directive, found string \"float x\""},
        {"LookAt 0 0 0\n 0 0 1", "scene.pbrt:1: LookAt: expected 9 numbers, found 6"},
        {"Translate 1 2 3 4", "scene.pbrt:1: Translate: expected 3 numbers, found 4"},
        {"Transform [1 0 0 0]", "scene.pbrt:1: Transform: expected 16 numbers, found 4"},
        {"Transform [1 0 \"a\"]", "scene.pbrt:1: Transform: expected ']' after the numbers, found string \"a\""},
        {"Shape\nWorldBegin", "scene.pbrt:1: Shape: expected 1 string, found 0 before bare word 'WorldBegin'"},
        {"Texture \"a\" \"spectrum\" 3", "scene.pbrt:1: Texture: expected 3 strings, found 2 before number 3"},
        {"MediumInterface 1", "scene.pbrt:1: MediumInterface: expected 1 or 2 strings, found 0 before number 1"},
        {"ActiveTransform Sometimes", "scene.pbrt:1: ActiveTransform: expected All, StartTime or EndTime, found bare word 'Sometimes'"},
        {"Scale 1 1e999 1", "scene.pbrt:1: number '1e999' is out of range"},
        {"Scale 1 1.2.3 1", "scene.pbrt:1: malformed number '1.2.3'"},
        {"Scale 1 -inf 1", "scene.pbrt:1: malformed number '-inf'"},
        {"\n@", "scene.pbrt:2: unexpected character '@'"},
        {"Shape \"a\\qb\"", "scene.pbrt:1: unknown escape '\\q' in a string"},
    };
    for (const auto& [text, message] : cases) EXPECT_EQ(errorOf(text), message) << text;
}

TEST(PbrtParser, ParseErrorCarriesLocationAndMessageApart) {
    try {
        parse("WorldBegin\n\nFoo");
        FAIL() << "no error";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.where().file, "scene.pbrt");
        EXPECT_EQ(e.where().line, 3);
        EXPECT_EQ(e.message(), "unknown directive 'Foo'");
    }
}

// A scene folder with files that include each other, and one outside it.
struct IncludeFolder {
    fs::path base = fs::temp_directory_path() / ("photon-pbrt-test-" + std::to_string(::getpid()));
    fs::path scene = base / "scene";

    IncludeFolder() {
        fs::remove_all(base);
        fs::create_directories(scene / "geometry/detail");
        write(scene / "scene.pbrt", "Camera \"perspective\"\nInclude \"geometry/walls.pbrt\"\nWorldEnd\n");
        write(scene / "geometry/walls.pbrt",
              "# walls\nShape \"sphere\"\nImport \"detail/trim.pbrt\"\nShape \"disk\" \"float radius\" \"big\"\n");
        write(scene / "geometry/detail/trim.pbrt", "Shape \"cylinder\"\n\nShape \"bilinearmesh\"\n");
        write(scene / "loop_a.pbrt", "Include \"geometry/loop_b.pbrt\"\n");
        write(scene / "geometry/loop_b.pbrt", "\nInclude \"../loop_a.pbrt\"\n");
        write(scene / "self.pbrt", "WorldBegin\nInclude \"self.pbrt\"\n");
        write(scene / "escape.pbrt", "Include \"../outside.pbrt\"\n");
        write(scene / "absolute.pbrt", "Include \"" + (base / "outside.pbrt").string() + "\"\n");
        write(scene / "missing.pbrt", "\nInclude \"nothere.pbrt\"\n");
        write(scene / "through_link.pbrt", "Include \"link.pbrt\"\n");
        write(base / "outside.pbrt", "WorldBegin\n");
        fs::create_symlink(base / "outside.pbrt", scene / "link.pbrt");
        // A chain of 5 files, each including the next.
        for (int i = 0; i < 5; ++i)
            write(scene / ("chain" + std::to_string(i) + ".pbrt"),
                  i < 4 ? "Include \"chain" + std::to_string(i + 1) + ".pbrt\"\n" : "WorldBegin\n");
    }
    ~IncludeFolder() {
        std::error_code ec;
        fs::remove_all(base, ec);
    }
    static void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

    std::string errorOf(const std::string& file, const ParseLimits& limits = {}) const {
        try {
            parseFile(scene / file, scene, [](Directive&&) {}, limits);
        } catch (const ParseError& e) {
            return e.what();
        }
        return "";
    }
};

TEST(PbrtParser, IncludeAndImportAreInlinedRelativeToTheIncludingFile) {
    IncludeFolder folder;
    std::vector<std::string> seen;
    try {
        parseFile(folder.scene / "scene.pbrt", folder.scene, [&](Directive&& d) {
            seen.push_back(d.name + (d.strings.empty() ? "" : " " + d.strings[0]) + " @" + d.where.str());
        });
        FAIL() << "the bad radius was not reported";
    } catch (const ParseError& e) {
        // The error after the import names the including file and its own line.
        EXPECT_STREQ(e.what(), "geometry/walls.pbrt:4: parameter \"float radius\" expects numbers, found string \"big\"");
    }
    EXPECT_EQ(seen, (std::vector<std::string>{"Camera perspective @scene.pbrt:1", "Shape sphere @geometry/walls.pbrt:2",
                                              "Shape cylinder @geometry/detail/trim.pbrt:1",
                                              "Shape bilinearmesh @geometry/detail/trim.pbrt:3"}));
}

TEST(PbrtParser, IncludesMustStayInsideTheSceneFolder) {
    IncludeFolder folder;
    EXPECT_EQ(folder.errorOf("escape.pbrt"), "escape.pbrt:1: Include \"../outside.pbrt\": outside the scene's folder");
    EXPECT_EQ(folder.errorOf("through_link.pbrt"), "through_link.pbrt:1: Include \"link.pbrt\": outside the scene's folder");
    EXPECT_EQ(folder.errorOf("absolute.pbrt"),
              "absolute.pbrt:1: Include \"" + (folder.base / "outside.pbrt").string() +
                  "\": absolute paths are refused; name the file relative to the including file");
    EXPECT_EQ(folder.errorOf("missing.pbrt"), "missing.pbrt:2: Include \"nothere.pbrt\": file not found");
}

TEST(PbrtParser, IncludeCyclesAndDepthAreRefused) {
    IncludeFolder folder;
    EXPECT_EQ(folder.errorOf("self.pbrt"), "self.pbrt:2: Include \"self.pbrt\": the file includes itself (an include cycle)");
    EXPECT_EQ(folder.errorOf("loop_a.pbrt"),
              "geometry/loop_b.pbrt:2: Include \"../loop_a.pbrt\": the file includes itself (an include cycle)");
    EXPECT_EQ(folder.errorOf("chain0.pbrt"), "");
    ParseLimits shallow;
    shallow.maxIncludeDepth = 3;
    EXPECT_EQ(folder.errorOf("chain0.pbrt", shallow), "chain3.pbrt:1: Include \"chain4.pbrt\": includes nested more than 3 deep");
    ParseLimits few;
    few.maxFiles = 2;
    EXPECT_EQ(folder.errorOf("chain0.pbrt", few), "chain1.pbrt:1: Include \"chain2.pbrt\": more than 2 files read");
    ParseLimits small;
    small.maxTotalBytes = 50;  // each file is 22 bytes
    EXPECT_EQ(folder.errorOf("chain0.pbrt", small), "chain1.pbrt:1: Include \"chain2.pbrt\": the scene's files exceed 50 bytes");
}

// pbrt-v4 reads an included file's tokens where its Include stands, so a directive that the
// file's last lines begin goes on in the includer: here a mesh's indices follow the Include.
TEST(PbrtParser, AParameterListGoesOnAfterTheEndOfAnIncludedFile) {
    IncludeFolder folder;
    IncludeFolder::write(folder.scene / "split.pbrt",
                         "WorldBegin\nInclude \"geometry/mesh.pbrt\"\n  \"integer indices\" [0 1 2]\nShape \"disk\"\n");
    IncludeFolder::write(folder.scene / "geometry/mesh.pbrt", "Shape \"trianglemesh\"\n  \"point3 P\" [0 0 0 1 0 0\n0 1 0]\n");
    std::vector<Directive> seen;
    parseFile(folder.scene / "split.pbrt", folder.scene, [&](Directive&& d) { seen.push_back(std::move(d)); });
    ASSERT_EQ(seen.size(), 3u);
    EXPECT_EQ(seen[1].name, "Shape");
    EXPECT_EQ(seen[1].where.str(), "geometry/mesh.pbrt:1");
    ASSERT_EQ(seen[1].params.size(), 2u);
    EXPECT_EQ(seen[1].params[0].numbers, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
    EXPECT_EQ(seen[1].params[0].where.str(), "geometry/mesh.pbrt:2");
    EXPECT_EQ(seen[1].params[1].name, "indices");
    EXPECT_EQ(seen[1].params[1].numbers, (std::vector<double>{0, 1, 2}));
    EXPECT_EQ(seen[1].params[1].where.str(), "split.pbrt:3");
    EXPECT_EQ(seen[2].strings, (std::vector<std::string>{"disk"}));
    EXPECT_EQ(seen[2].where.str(), "split.pbrt:4");

    // An error that spans the two names both places: a '[' the included file leaves open.
    IncludeFolder::write(folder.scene / "open.pbrt", "WorldBegin\nInclude \"geometry/open.pbrt\"\nWorldEnd\n");
    IncludeFolder::write(folder.scene / "geometry/open.pbrt", "Shape \"trianglemesh\" \"point3 P\" [0 0 0\n");
    EXPECT_EQ(folder.errorOf("open.pbrt"),
              "geometry/open.pbrt:1: unbalanced '[': parameter \"point3 P\" has no ']' before WorldEnd at open.pbrt:3");
}

TEST(PbrtParser, MissingOrOversizedSceneFiles) {
    IncludeFolder folder;
    try {
        parseFile(folder.scene / "none.pbrt", folder.scene, [](Directive&&) {});
        FAIL() << "no error";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.where().str(), "none.pbrt:0");
        EXPECT_EQ(e.message(), "scene file '" + (folder.scene / "none.pbrt").string() + "' not found");
    }
    ParseLimits tiny;
    tiny.maxTotalBytes = 8;
    EXPECT_EQ(folder.errorOf("scene.pbrt", tiny), "scene.pbrt:0: the scene file exceeds 8 bytes");
    try {
        parseText("WorldBegin WorldEnd", "text.pbrt", folder.scene, [](Directive&&) {}, tiny);
        FAIL() << "no error";
    } catch (const ParseError& e) {
        EXPECT_STREQ(e.what(), "text.pbrt:0: the scene file exceeds 8 bytes");
    }
}

// pbrt-v4 scenes ship their large geometry files gzipped ("geometry/hair.pbrt.gz").
TEST(PbrtParser, GzippedFilesAreReadAsTheTextTheyHold) {
    IncludeFolder folder;
    const fs::path& scene = folder.scene;
    IncludeFolder::write(scene / "zipped.pbrt", "WorldBegin\nInclude \"geometry/walls.pbrt.gz\"\nShape \"disk\"\n");
    IncludeFolder::write(scene / "geometry/walls.pbrt.gz",
                         test::gzipped("# walls\nShape \"sphere\"\n") + test::gzipped("Shape \"cylinder\"\n"));
    std::vector<std::string> seen;
    parseFile(scene / "zipped.pbrt", scene, [&](Directive&& d) {
        seen.push_back(d.name + (d.strings.empty() ? "" : " " + d.strings[0]) + " @" + d.where.str());
    });
    // Two gzip members one after the other are one text (as `cat a.gz b.gz`), lines counted on.
    EXPECT_EQ(seen, (std::vector<std::string>{"WorldBegin @zipped.pbrt:1", "Shape sphere @geometry/walls.pbrt.gz:2",
                                              "Shape cylinder @geometry/walls.pbrt.gz:3", "Shape disk @zipped.pbrt:3"}));
    // The main file may be gzipped too.
    IncludeFolder::write(scene / "main.pbrt.gz", test::gzipped("WorldBegin\nShape \"sphere\" \"float radius\" \"big\"\n"));
    EXPECT_EQ(folder.errorOf("main.pbrt.gz"),
              "main.pbrt.gz:2: parameter \"float radius\" expects numbers, found string \"big\"");

    // Cut short, damaged, or inflating past the scene's byte limit: refused, naming the file.
    const std::string whole = test::gzipped(std::string(4000, ' ') + "WorldBegin\n");
    IncludeFolder::write(scene / "cut.pbrt.gz", whole.substr(0, whole.size() / 2));
    IncludeFolder::write(scene / "cut.pbrt", "\nInclude \"cut.pbrt.gz\"\n");
    EXPECT_EQ(folder.errorOf("cut.pbrt"), "cut.pbrt:2: Include cut.pbrt.gz: the gzip file is cut short");
    std::string damaged = whole;
    damaged[damaged.size() - 3] ^= 0x55;  // in the trailer's length: the CRC check catches it
    IncludeFolder::write(scene / "damaged.pbrt.gz", damaged);
    IncludeFolder::write(scene / "damaged.pbrt", "Include \"damaged.pbrt.gz\"\n");
    EXPECT_EQ(folder.errorOf("damaged.pbrt"),
              "damaged.pbrt:1: Include damaged.pbrt.gz: damaged gzip data (incorrect length check)");
    IncludeFolder::write(scene / "bomb.pbrt.gz", test::gzipped(std::string(1 << 20, '#')));
    IncludeFolder::write(scene / "bomb.pbrt", "Include \"bomb.pbrt.gz\"\n");
    ParseLimits small;
    small.maxTotalBytes = 100000;  // the compressed file is about a kilobyte
    EXPECT_EQ(folder.errorOf("bomb.pbrt", small),
              "bomb.pbrt:1: Include \"bomb.pbrt.gz\": the scene's files exceed 100000 bytes");
    EXPECT_EQ(folder.errorOf("bomb.pbrt"), "");
}

TEST(PbrtParser, TextInMemoryIncludesAgainstTheRoot) {
    IncludeFolder folder;
    std::vector<std::string> shapes;
    parseText("Include \"detail/trim.pbrt\"", "geometry/inline.pbrt", folder.scene, [&](Directive&& d) {
        shapes.push_back(d.strings[0] + " @" + d.where.str());
    });
    EXPECT_EQ(shapes, (std::vector<std::string>{"cylinder @geometry/detail/trim.pbrt:1",
                                                "bilinearmesh @geometry/detail/trim.pbrt:3"}));
}

std::vector<const Directive*> named(const std::vector<Directive>& all, std::string_view name) {
    std::vector<const Directive*> out;
    for (const Directive& d : all)
        if (d.name == name) out.push_back(&d);
    return out;
}

TEST(PbrtRealScenes, CoffeeMaker) {
    auto d = parse(test::kCoffeeScene);
    EXPECT_EQ(d.size(), 61u);
    EXPECT_EQ(named(d, "Shape").size(), 23u);
    EXPECT_EQ(named(d, "MakeNamedMaterial").size(), 5u);
    ASSERT_EQ(named(d, "Transform").size(), 1u);
    EXPECT_DOUBLE_EQ(named(d, "Transform")[0]->numbers[14], 0.835307);
    const Directive& metal = *named(d, "MakeNamedMaterial")[3];
    EXPECT_EQ(metal.strings, std::vector<std::string>{"Metal"});
    EXPECT_EQ(metal.find("eta")->type, "spectrum");
    EXPECT_EQ(metal.find("eta")->strings, std::vector<std::string>{"metal-Ag-eta"});
    EXPECT_EQ(named(d, "MakeNamedMaterial")[0]->find("remaproughness")->bools, std::vector<bool>{false});
    EXPECT_EQ(named(d, "Shape")[0]->find("filename")->strings, std::vector<std::string>{"models/Mesh013.ply"});
    EXPECT_EQ(named(d, "Shape")[0]->where.str(), "scene.pbrt:47");
    EXPECT_EQ(named(d, "Film")[0]->find("yresolution")->numbers, std::vector<double>{1000});
}

TEST(PbrtRealScenes, CornellBox) {
    auto d = parse(test::kCornellBoxExcerpt);
    auto shapes = named(d, "Shape");
    ASSERT_EQ(shapes.size(), 2u);
    EXPECT_EQ(shapes[0]->find("indices")->numbers, (std::vector<double>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(shapes[0]->find("P")->numbers.size(), 12u);
    EXPECT_DOUBLE_EQ(shapes[0]->find("P")->numbers[1], 1.74846e-7);
    EXPECT_EQ(shapes[0]->find("N")->type, "normal");
    EXPECT_EQ(named(d, "Camera")[0]->find("fov")->numbers, std::vector<double>{19.5});
    EXPECT_EQ(named(d, "Film")[0]->find("xresolution")->numbers, std::vector<double>{64});
    EXPECT_EQ(named(d, "PixelFilter").size(), 1u);  // the other two are commented out
    EXPECT_EQ(named(d, "AreaLightSource")[0]->find("L")->numbers, (std::vector<double>{17, 12, 4}));
    EXPECT_EQ(named(d, "MakeNamedMaterial")[0]->find("reflectance")->numbers, (std::vector<double>{0.63, 0.065, 0.05}));
}

TEST(PbrtRealScenes, VeachMis) {
    auto d = parse(test::kVeachMisExcerpt);
    EXPECT_EQ(named(d, "Shape").size(), 2u);
    EXPECT_EQ(named(d, "Camera")[0]->find("fov")->numbers, std::vector<double>{20.114292});
    const Directive& smooth = *named(d, "MakeNamedMaterial")[1];
    EXPECT_EQ(smooth.strings, std::vector<std::string>{"Smooth"});
    EXPECT_EQ(smooth.find("eta")->numbers, (std::vector<double>{0.200438, 0.924033, 1.102212}));
    EXPECT_EQ(named(d, "Shape")[1]->find("radius")->numbers, std::vector<double>{0.5});
    EXPECT_EQ(named(d, "AttributeBegin").size(), 4u);
    EXPECT_EQ(named(d, "AttributeEnd").size(), 4u);
}

}  // namespace
}  // namespace photon::pbrt
