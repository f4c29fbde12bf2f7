// Requests a web page could forge: cross-site submissions and cancels, bodies a form can
// send without asking (text/plain), and names rebound to the loopback address. Each is
// refused before anything happens; the server's own page, curl and the other clients that
// send no Origin go on working.
#include "server_fixture.h"

namespace photon::test {
namespace {

class OriginTest : public ServerTest {
protected:
    std::string self() const { return "127.0.0.1:" + std::to_string(port()); }
    httplib::Result postScene(const httplib::Headers& headers, const std::string& type = "application/json") {
        return client().Post("/api/v1/jobs", headers, smallScene(1).dump(), type.c_str());
    }
    int jobCount() { return json::parse(client().Get("/api/v1/jobs")->body)["total"].get<int>(); }
};

TEST_F(OriginTest, ACrossSiteSubmissionIsRefusedAndQueuesNothing) {
    startServer({"--workers", "0"});
    httplib::Result plain = postScene({{"Origin", "http://evil.example"}}, "text/plain");
    ASSERT_TRUE(plain);
    EXPECT_EQ(plain->status, 403);
    EXPECT_EQ(json::parse(plain->body)["error"],
              "requests from http://evil.example may not change anything here (--allow-origin lists the sites "
              "that may)");
    EXPECT_EQ(postScene({{"Origin", "http://evil.example"}})->status, 403);
    EXPECT_EQ(postScene({{"Origin", "null"}})->status, 403);  // sandboxed frames, file:// pages
    EXPECT_EQ(postScene({{"Sec-Fetch-Site", "cross-site"}})->status, 403);
    EXPECT_EQ(postScene({{"Sec-Fetch-Site", "same-site"}})->status, 403);  // another port of localhost
    EXPECT_EQ(jobCount(), 0);
}

TEST_F(OriginTest, TheServersOwnPageAndClientsWithoutOriginMaySubmit) {
    startServer({"--workers", "0"});
    EXPECT_EQ(postScene({{"Origin", "http://" + self()}, {"Sec-Fetch-Site", "same-origin"}})->status, 201);
    EXPECT_EQ(postScene({})->status, 201);  // curl, scripts
    EXPECT_EQ(postScene({{"Sec-Fetch-Site", "none"}})->status, 201);  // typed into the address bar
    EXPECT_EQ(jobCount(), 3);
}

TEST_F(OriginTest, AListedOriginMaySubmit) {
    startServer({"--workers", "0", "--allow-origin", "https://farm.example.com"});
    EXPECT_EQ(postScene({{"Origin", "https://farm.example.com"}, {"Sec-Fetch-Site", "cross-site"}})->status, 201);
    EXPECT_EQ(postScene({{"Origin", "https://other.example.com"}})->status, 403);
}

TEST_F(OriginTest, ABodyThatIsNeitherJsonNorMultipartIsRefused) {
    startServer({"--workers", "0"});
    for (const char* type : {"text/plain", "application/x-www-form-urlencoded", "application/octet-stream"}) {
        httplib::Result r = postScene({}, type);
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, 415) << type;
        EXPECT_EQ(json::parse(r->body)["error"], std::string("a request body must be application/json or "
                                                             "multipart/form-data, not \"") + type + "\"");
    }
    EXPECT_EQ(postScene({}, "application/json; charset=utf-8")->status, 201);
    EXPECT_EQ(jobCount(), 1);
}

TEST_F(OriginTest, ACrossSiteCancelIsRefusedAndABodylessOneFromHereWorks) {
    startServer({"--workers", "0"});
    std::string id = submitOk(smallScene());
    const std::string path = "/api/v1/jobs/" + id + "/cancel";
    EXPECT_EQ(client().Post(path.c_str(), {{"Origin", "http://evil.example"}}, "", "text/plain")->status, 403);
    EXPECT_EQ(client().Delete(("/api/v1/jobs/" + id).c_str(), {{"Origin", "http://evil.example"}})->status, 403);
    EXPECT_EQ(getJob(id)["status"], "queued");
    EXPECT_EQ(client().Post(path.c_str(), httplib::Headers{{"Origin", "http://" + self()}})->status, 200);
}

TEST_F(OriginTest, AnotherHostNameIsRefusedUnlessListed) {
    startServer({"--workers", "0"});
    httplib::Client c = client();
    httplib::Result rebound = c.Get("/api/v1/jobs", {{"Host", "evil.example:" + std::to_string(port())}});
    ASSERT_TRUE(rebound);
    EXPECT_EQ(rebound->status, 421);
    EXPECT_EQ(c.Get("/", {{"Host", "evil.example"}})->status, 421);  // the page too
    EXPECT_EQ(c.Get("/api/v1/jobs", {{"Host", "localhost:" + std::to_string(port())}})->status, 200);
    EXPECT_EQ(c.Get("/api/v1/jobs", {{"Host", "[::1]:" + std::to_string(port())}})->status, 200);
    EXPECT_EQ(c.Get("/api/v1/jobs", {{"Host", "127.0.0.1:1"}})->status, 421);  // another port
    EXPECT_EQ(c.Get("/api/v1/jobs", {{"Host", "127.0.0.1:x"}})->status, 421);

    stopServer();
    startServer({"--workers", "0", "--allow-host", "render.example.com"});
    EXPECT_EQ(client().Get("/api/v1/jobs", {{"Host", "render.example.com"}})->status, 200);
    EXPECT_EQ(client().Get("/api/v1/jobs", {{"Host", "RENDER.example.com:443"}})->status, 200);
    EXPECT_EQ(client().Get("/api/v1/jobs", {{"Host", "evil.example"}})->status, 421);
}

// A refusal comes before the body is read: the connection is then closed (and says so), so
// that the unread body is never taken for a next request and a pipelined one never silently
// goes unanswered on it.
TEST_F(OriginTest, ARefusedRequestsConnectionIsClosed) {
    startServer({"--workers", "0"});
    const std::string body = smallScene(1).dump();
    const std::string host = "Host: " + self() + "\r\n";
    const std::string requests = "POST /api/v1/jobs HTTP/1.1\r\n" + host +
                                 "Content-Type: text/plain\r\nContent-Length: " + std::to_string(body.size()) +
                                 "\r\n\r\n" + body + "GET /api/v1/health HTTP/1.1\r\n" + host + "\r\n";
    const std::string answer = rawExchange(port(), requests);
    EXPECT_EQ(answer.rfind("HTTP/1.1 415 Unsupported Media Type\r\n", 0), 0u) << answer;
    EXPECT_NE(answer.find("\r\nConnection: close\r\n"), std::string::npos) << answer;
    EXPECT_EQ(answer.find("HTTP/1.1", 1), std::string::npos) << "a second answer: " << answer;
}

}  // namespace
}  // namespace photon::test
