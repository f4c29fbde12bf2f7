// Requests whose framing is in doubt are refused (RFC 9112 6.3: a proxy that read them
// otherwise could smuggle a request through), and a POST without a body, as `curl -X POST`
// sends it, is an ordinary request.
#include "server_fixture.h"

namespace photon::test {
namespace {

class FramingTest : public ServerTest {
protected:
    // A POST of `body` with the given framing headers; the whole answer.
    std::string post(const std::string& framing, const std::string& body) {
        return rawExchange(port(), "POST /api/v1/jobs HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port()) +
                                       "\r\nContent-Type: application/json\r\n" + framing + "\r\n" + body);
    }
    static void expectRefused(const std::string& answer, const std::string& message) {
        EXPECT_EQ(answer.rfind("HTTP/1.1 400 Bad Request\r\n", 0), 0u) << answer;
        EXPECT_NE(answer.find("\r\nConnection: close\r\n"), std::string::npos) << answer;
        EXPECT_EQ(problemOf(answer)["detail"], message) << answer;
    }
};

TEST_F(FramingTest, AmbiguousLengthsAreRefused) {
    startServer({"--workers", "0"});
    const std::string body = smallScene(1).dump();
    const std::string length = std::to_string(body.size());
    expectRefused(post("Content-Length: " + length + "\r\nContent-Length: 5\r\n", body),
                  "two different Content-Length headers");
    expectRefused(post("Content-Length: " + length + "\r\nTransfer-Encoding: chunked\r\n", body),
                  "both Transfer-Encoding and Content-Length");
    expectRefused(post("Content-Length: -1\r\n", body),
                  "Content-Length: expected a whole number of bytes, got \"-1\"");
    expectRefused(post("Transfer-Encoding: gzip, chunked\r\n", "0\r\n\r\n"), "Transfer-Encoding: only chunked is accepted");
    EXPECT_EQ(json::parse(client().Get("/api/v1/jobs")->body)["total"], 0);
    // The same length twice says nothing new (RFC 9110 8.6): an ordinary request.
    std::string same = post("Content-Length: " + length + "\r\nContent-Length: " + length + "\r\nConnection: close\r\n", body);
    EXPECT_EQ(same.rfind("HTTP/1.1 201 Created\r\n", 0), 0u) << same;
}

TEST_F(FramingTest, APathWithAControlCharacterIsNotFound) {
    startServer({"--workers", "0"});
    for (const char* path : {"/index.html%00.js", "/index.html%0a", "/api/v1/jobs%00"}) {
        httplib::Result r = client().Get(path);
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, 404) << path;
        EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json") << path;
    }
    EXPECT_EQ(client().Get("/index.html")->get_header_value("Content-Type"), "text/html");
}

TEST_F(FramingTest, APostWithoutABodyIsAnOrdinaryRequest) {
    startServer({"--workers", "0"});
    std::string id = submitOk(smallScene());
    // What `curl -X POST URL` sends: no Content-Length, no Transfer-Encoding.
    std::string answer = rawExchange(port(), "POST /api/v1/jobs/" + id + "/cancel HTTP/1.1\r\nHost: 127.0.0.1:" +
                                                 std::to_string(port()) + "\r\nConnection: close\r\n\r\n");
    EXPECT_EQ(answer.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << answer;
    EXPECT_EQ(getJob(id)["status"], "cancelled");
}

}  // namespace
}  // namespace photon::test
