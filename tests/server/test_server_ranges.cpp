// Range headers cannot amplify a response: the API (images included) and metrics are always
// sent whole, and the page's files honour at most a few ranges in order without overlaps.
#include "server_fixture.h"

namespace photon::test {
namespace {

class RangesTest : public ServerTest {
protected:
    httplib::Result get(const std::string& path, const std::string& range) {
        return client().Get(path.c_str(), {{"Range", "bytes=" + range}});
    }
};

std::string repeated(const std::string& range, int times) {
    std::string out;
    for (int i = 0; i < times; ++i) out += (i ? "," : "") + range;
    return out;
}

TEST_F(RangesTest, TheApiAndMetricsIgnoreRangesAndAreSentWhole) {
    startServer({"--workers", "0"});
    for (int i = 0; i < 3; ++i) submitOk(smallScene());
    const std::string whole = client().Get("/api/v1/jobs?limit=1000")->body;
    // 2,600 ranges in 7.8 KB of header once made a multipart response of every one of them.
    httplib::Result amplified = get("/api/v1/jobs?limit=1000", repeated("0-", 2600));
    ASSERT_TRUE(amplified);
    EXPECT_EQ(amplified->status, 200);
    EXPECT_EQ(amplified->body, whole);
    httplib::Result one = get("/api/v1/jobs", "0-9");
    EXPECT_EQ(one->status, 200);
    EXPECT_EQ(one->body, whole);
    httplib::Result metrics = get("/metrics", "0-9");
    EXPECT_EQ(metrics->status, 200);
    EXPECT_GT(metrics->body.size(), 10u);
}

TEST_F(RangesTest, ImagesAreSentWhole) {
    // httplib would send a range of an image with status 200, as if it were all of it.
    startServer();
    std::string id = submitOk(smallScene(1, 2000, 32));
    waitForStatus(id, "completed");
    const std::string path = "/api/v1/jobs/" + id + "/image?format=exr";
    const std::string whole = client().Get(path.c_str())->body;
    ASSERT_GT(whole.size(), 100u);
    for (const std::string& range : {std::string("0-9"), std::string("-16"), std::string("0-9,20-29")}) {
        httplib::Result r = get(path, range);
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, 200) << range;
        EXPECT_EQ(r->body, whole) << range;
    }
}

TEST_F(RangesTest, ThePagesFilesHonourAFewOrderedRangesAndNothingElse) {
    startServer({"--workers", "0"});
    const std::string page = client().Get("/")->body;
    ASSERT_GT(page.size(), 100u);
    httplib::Result first = get("/", "0-99");
    EXPECT_EQ(first->status, 206);
    EXPECT_EQ(first->body, page.substr(0, 100));
    httplib::Result tail = get("/", "-16");
    EXPECT_EQ(tail->status, 206);
    EXPECT_EQ(tail->body, page.substr(page.size() - 16));
    httplib::Result two = get("/", "0-9,20-29");
    EXPECT_EQ(two->status, 206);
    EXPECT_NE(two->get_header_value("Content-Type").find("multipart/byteranges"), std::string::npos);
    EXPECT_NE(two->body.find(page.substr(20, 10)), std::string::npos);
    for (const std::string& ignored : {repeated("0-", 2600), repeated("0-0", 5), std::string("0-9,5-20"),
                                       std::string("20-29,0-9"), std::string("0-,10-19"), std::string("0-9,-5")}) {
        httplib::Result r = get("/", ignored);
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, 200) << ignored.substr(0, 20);
        EXPECT_EQ(r->body, page) << ignored.substr(0, 20);
    }
}

}  // namespace
}  // namespace photon::test
