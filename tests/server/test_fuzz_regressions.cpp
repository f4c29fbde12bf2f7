// Inputs the fuzz targets (tests/fuzz) found mishandled, each kept as a test with the fix.
#include "server_fixture.h"

namespace photon::test {
namespace {

class FuzzRegressionsTest : public ServerTest {
protected:
    // Posts the scene with one or two assets and expects a 400 whose error names the reason
    // and the last asset's file name.
    void expectRefused(const std::vector<std::string>& assetNames, const std::string& reason) {
        httplib::MultipartFormDataItems items{{"scene", smallScene().dump(), "", "application/json"}};
        for (const std::string& name : assetNames) items.push_back({"asset", "v 0 0 0\n", name, "text/plain"});
        httplib::Result r = client().Post("/api/v1/jobs", items);
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, 400) << r->body;
        EXPECT_EQ(json::parse(r->body)["error"],
                  reason + ": part \"asset\" (file name \"" + assetNames.back() + "\")")
            << r->body;
    }
};

// fuzz_http: assets "meshes/tri.obj/x" and "meshes/tri.obj" in one upload made the second
// file impossible to create (a folder of that name exists, or the reverse) and the server
// answered 500. Now a 400 naming the asset, in either order, and nothing is left behind.
TEST_F(FuzzRegressionsTest, AssetThatIsAlsoAnotherAssetsFolderIs400) {
    startServer({"--workers", "0"});
    const std::vector<std::pair<std::string, std::string>> orders{{"meshes/tri.obj/x", "meshes/tri.obj"},
                                                                  {"meshes/tri.obj", "meshes/./tri.obj/x"}};
    for (const auto& [first, second] : orders)
        expectRefused({first, second}, "asset name is both a file and a folder");
    EXPECT_TRUE(std::filesystem::is_empty(dataDir() / "jobs"));
    EXPECT_TRUE(std::filesystem::is_empty(dataDir() / "tmp"));
}

// fuzz_http: a folder or file name over the file system's 255-byte limit made creating the
// asset fail with ENAMETOOLONG and the server answered 500. Now a 400 naming the reason.
TEST_F(FuzzRegressionsTest, AssetNamePartOver255BytesIs400) {
    startServer({"--workers", "0"});
    const std::string longPart(256, 'I');
    for (const std::string& name : {"meshes/" + longPart + "/tri.obj", "meshes/" + longPart})
        expectRefused({name}, "asset name has a component longer than 255 bytes");
    // 255 bytes is still a valid name.
    httplib::MultipartFormDataItems ok{
        {"scene", smallScene().dump(), "", "application/json"},
        {"asset", "v 0 0 0\n", "meshes/" + std::string(255, 'I'), "text/plain"},
    };
    httplib::Result r = client().Post("/api/v1/jobs", ok);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 201) << r->body;
}

}  // namespace
}  // namespace photon::test
