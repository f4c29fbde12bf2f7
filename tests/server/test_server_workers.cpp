// Several render workers at once, and the live image stream of a running job.
#include "server_fixture.h"

namespace photon::test {
namespace {

class WorkersTest : public ServerTest {
protected:
    // The cancel's status: 202 for a running job (it stops within a pass), 200 for a queued one.
    int cancel(const std::string& id) {
        httplib::Result r = client().Post(("/api/v1/jobs/" + id + "/cancel").c_str());
        return r ? r->status : -1;
    }
    std::string status(const std::string& id) { return getJob(id)["status"]; }
};

TEST_F(WorkersTest, TwoWorkersRenderTwoJobsAtOnceAndCancellingOneLeavesTheOther) {
    startServer({"--workers", "2"});
    std::string first = submitOk(longScene()), second = submitOk(longScene());
    waitForStatus(first, "running");
    waitForStatus(second, "running");
    // Both advance side by side.
    json a = waitFor(first, [](const json& j) { return j["pass"].get<int>() >= 2; });
    json b = waitFor(second, [](const json& j) { return j["pass"].get<int>() >= 2; });
    EXPECT_EQ(a["status"], "running");
    EXPECT_EQ(b["status"], "running");

    ASSERT_EQ(cancel(first), 202);
    EXPECT_EQ(waitForStatus(first, "cancelled")["status"], "cancelled");
    int passesThen = getJob(second)["pass"];
    json later = waitFor(second, [&](const json& j) { return j["pass"].get<int>() > passesThen + 1; });
    EXPECT_EQ(later["status"], "running");

    // The freed worker takes the next job while the other still renders.
    std::string third = submitOk(smallScene(2));
    EXPECT_EQ(waitForStatus(third, "completed")["status"], "completed");
    EXPECT_EQ(status(second), "running");
    ASSERT_EQ(cancel(second), 202);
    EXPECT_EQ(waitForStatus(second, "cancelled")["status"], "cancelled");
}

TEST_F(WorkersTest, WithEveryWorkerBusyTheHigherPriorityJobStartsFirst) {
    startServer({"--workers", "2"});
    std::string busy1 = submitOk(longScene()), busy2 = submitOk(longScene());
    waitForStatus(busy1, "running");
    waitForStatus(busy2, "running");
    std::string low = submitOk(longScene(), "?priority=-1");
    std::string high = submitOk(longScene(), "?priority=3");
    std::string normal = submitOk(longScene());
    ASSERT_EQ(cancel(busy1), 202);
    EXPECT_EQ(waitForStatus(high, "running")["status"], "running");
    EXPECT_EQ(status(low), "queued");
    EXPECT_EQ(status(normal), "queued");
    ASSERT_EQ(cancel(busy2), 202);
    EXPECT_EQ(waitForStatus(normal, "running")["status"], "running");
    EXPECT_EQ(status(low), "queued");
    EXPECT_EQ(cancel(low), 200);
    EXPECT_EQ(cancel(high), 202);
    EXPECT_EQ(cancel(normal), 202);
}

TEST_F(WorkersTest, TheLiveStreamSendsNewFramesWhileTheJobRuns) {
    // A job of about three seconds on this machine: frames come at most every 250 ms, so a
    // stream that follows it sees several passes however fast the machine renders.
    const int passes = passesLasting(3, 20000, 32);
    startServer();
    std::string id = submitOk(smallScene(passes, 20000, 32));
    std::string body;
    httplib::Result r = client().Get(("/api/v1/jobs/" + id + "/stream").c_str(), [&](const char* data, size_t n) {
        body.append(data, n);
        return true;
    });
    ASSERT_TRUE(r && r->status == 200);
    EXPECT_EQ(r->get_header_value("Content-Type"), "multipart/x-mixed-replace; boundary=frame");

    std::vector<int> framePasses;
    const std::string field = "\r\nX-Photon-Pass: ";
    for (size_t at = body.find(field); at != std::string::npos; at = body.find(field, at + 1))
        framePasses.push_back(std::stoi(body.substr(at + field.size(), 12)));
    ASSERT_GE(framePasses.size(), 3u) << "frames for passes only at the start and the end";
    for (size_t i = 1; i < framePasses.size(); ++i) EXPECT_GT(framePasses[i], framePasses[i - 1]);
    EXPECT_EQ(framePasses.back(), passes);
    EXPECT_EQ(body.substr(body.size() - 11), "--frame--\r\n");  // the stream's closing boundary
}

}  // namespace
}  // namespace photon::test
