// The connection guard's parsers on their own: where a head ends and what it says, and where
// a chunked body ends, fed in pieces as bytes arrive.
#include <gtest/gtest.h>
#include <algorithm>
#include <variant>
#include "api/chunked_body.h"
#include "api/request_framing.h"
#include "api/request_head.h"
#include "api/request_relay.h"
#include "api/response_stream.h"

namespace photon::api {
namespace {

TEST(RequestHead, AWholeHeadIsParsedAndItsLengthCounted) {
    std::string bytes = "\r\nPOST /api/v1/jobs?x=1 HTTP/1.1\r\nHost: a\r\nContent-Length:  12 \r\n\r\nbody";
    HeadScan scan = scanRequestHead(bytes, {});
    ASSERT_EQ(scan.state, HeadScan::State::Complete);
    EXPECT_EQ(scan.length, bytes.size() - 4);  // the leading empty line counted, the body not
    EXPECT_EQ(scan.head.method, "POST");
    EXPECT_EQ(scan.head.target, "/api/v1/jobs?x=1");
    EXPECT_EQ(scan.head.values("content-length"), std::vector<std::string>{"12"});
    EXPECT_EQ(forwardedHead(scan.head, "10.0.0.1"),
              "POST /api/v1/jobs?x=1 HTTP/1.1\r\nHost: a\r\nContent-Length: 12\r\nX-Photon-Client-Address: 10.0.0.1\r\n\r\n");
}

TEST(RequestHead, EveryPrefixOfAHeadIsIncomplete) {
    std::string bytes = "GET / HTTP/1.1\r\nHost: a\r\n\r\n";
    for (size_t n = 0; n < bytes.size(); ++n)
        EXPECT_EQ(scanRequestHead(bytes.substr(0, n), {}).state, HeadScan::State::Incomplete) << n;
}

TEST(RequestHead, BoundsAreCheckedBeforeTheHeadEnds) {
    HeadLimits limits{100, 2};
    HeadScan line = scanRequestHead("GET /" + std::string(200, 'a'), limits);
    EXPECT_EQ(line.refusal.status, 414);
    HeadScan fields = scanRequestHead("GET / HTTP/1.1\r\na: 1\r\nb: 2\r\nc: 3\r\n", limits);
    EXPECT_EQ(fields.refusal.status, 431);
    EXPECT_EQ(scanRequestHead("GET / HTTP/1.1\r\na: 1\r\nb: 2\r\n\r\n", limits).state, HeadScan::State::Complete);
    HeadScan bytes = scanRequestHead("GET / HTTP/1.1\r\na: " + std::string(100, 'x'), limits);
    EXPECT_EQ(bytes.refusal.status, 431);
}

TEST(RequestHead, TheGuardsOwnFieldsReplaceTheClients) {
    HeadScan scan = scanRequestHead("GET / HTTP/1.1\r\nx-photon-client-address: 1.2.3.4\r\nX-Photon-Empty-Fields: A\r\n"
                                    "Idempotency-Key:\r\nB: 1\r\nC:  \r\n\r\n", {});
    EXPECT_EQ(forwardedHead(scan.head, "::1"),
              "GET / HTTP/1.1\r\nB: 1\r\nX-Photon-Client-Address: ::1\r\nX-Photon-Empty-Fields: Idempotency-Key, C\r\n\r\n");
}

TEST(BodyFraming, LengthsAndCodings) {
    auto framing = [](const std::string& fields) {
        return bodyFramingOf(scanRequestHead("POST / HTTP/1.1\r\n" + fields + "\r\n", {}).head);
    };
    EXPECT_EQ(std::get<BodyFraming>(framing("")).length, 0u);
    EXPECT_EQ(std::get<BodyFraming>(framing("Content-Length: 7\r\ncontent-length: 7\r\n")).length, 7u);
    EXPECT_EQ(std::get<BodyFraming>(framing("Transfer-Encoding: Chunked\r\n")).kind, BodyFraming::Kind::Chunked);
    EXPECT_EQ(std::get<Refusal>(framing("Content-Length: 7\r\nContent-Length: 8\r\n")).status, 400);
    EXPECT_EQ(std::get<Refusal>(framing("Content-Length: 99999999999999999999999\r\n")).status, 413);
    EXPECT_EQ(std::get<Refusal>(framing("Transfer-Encoding: chunked\r\nTransfer-Encoding: chunked\r\n")).status, 400);
}

TEST(ChunkedBody, TheEndIsFoundWhateverThePieces) {
    const std::string body = "5;name=value\r\nhello\r\n1A\r\n" + std::string(26, 'z') + "\r\n0\r\nTrailer: 1\r\n\r\n";
    const std::string next = "GET / HTTP/1.1\r\n";
    for (size_t piece : {1, 2, 3, 7, 64}) {
        ChunkedBodyScanner scanner;
        std::string all = body + next;
        size_t consumed = 0;
        std::string forward;
        for (size_t i = 0; i < all.size() && !scanner.done(); i += piece)
            consumed += scanner.consume(std::string_view(all).substr(i, piece), forward);
        EXPECT_TRUE(scanner.done()) << piece;
        EXPECT_EQ(consumed, body.size()) << piece;
        // Re-framed: plain sizes, no extension, no trailer.
        EXPECT_EQ(forward, "5\r\nhello\r\n1a\r\n" + std::string(26, 'z') + "\r\n0\r\n\r\n") << piece;
        EXPECT_FALSE(scanner.error());
    }
}

TEST(ChunkedBody, MalformedBodiesAreRefused) {
    for (const std::string& bad : std::vector<std::string>{"zz\r\n", "5\r\nhello!\r\n", "5\nhello\r\n", std::string(70000, '1')}) {
        ChunkedBodyScanner scanner;
        std::string forward;
        scanner.consume(bad, forward);
        ASSERT_TRUE(scanner.error()) << bad.substr(0, 20);
        EXPECT_EQ(scanner.error()->status, 400);
        EXPECT_FALSE(scanner.done());
    }
}

// Feeds `in` in pieces of `piece` bytes, each piece again until the relay takes no more.
std::string relayed(RequestRelay& relay, const std::string& in, size_t piece) {
    std::string forward, pending;
    for (size_t i = 0; i < in.size(); i += piece) {
        pending += in.substr(i, piece);
        for (size_t taken; !pending.empty() && (taken = relay.feed(pending, forward)) > 0;) pending.erase(0, taken);
    }
    return forward;
}

TEST(RequestRelay, RequestsGoOnWithTheClientsAddressAndTheirBodiesExactly) {
    const std::string in = "POST /a HTTP/1.1\r\nX-Photon-Client-Address: forged\r\nContent-Length: 3\r\n\r\nabc"
                           "POST /b HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n2;x\r\nde\r\n0\r\nT: 1\r\n\r\n"
                           "GET /c HTTP/1.1\r\n";
    const std::string out = "POST /a HTTP/1.1\r\nContent-Length: 3\r\nX-Photon-Client-Address: ::1\r\n\r\nabc"
                            "POST /b HTTP/1.1\r\nTransfer-Encoding: chunked\r\nX-Photon-Client-Address: ::1\r\n\r\n"
                            "2\r\nde\r\n0\r\n\r\n";
    for (size_t piece : {1, 5, 1000}) {
        RequestRelay relay({}, "::1");
        EXPECT_EQ(relayed(relay, in, piece), out) << piece;
        EXPECT_FALSE(relay.refusal());
        EXPECT_EQ(relay.requestsForwarded(), 2);
        EXPECT_TRUE(relay.midHead());
    }
}

TEST(RequestRelay, OneRequestAtATime) {
    RequestRelay relay({}, "::1");
    std::string forward;
    const std::string two = "GET /a HTTP/1.1\r\n\r\nPOST /b HTTP/1.1\r\nContent-Length: 1\r\n\r\nxGET";
    size_t first = relay.feed(two, forward);
    EXPECT_EQ(first, std::string("GET /a HTTP/1.1\r\n\r\n").size());
    EXPECT_EQ(relay.lastMethod(), "GET");
    size_t second = relay.feed(std::string_view(two).substr(first), forward);
    EXPECT_EQ(first + second, two.size() - 3);  // "GET" is the next request's
    EXPECT_EQ(relay.lastMethod(), "POST");
}

TEST(RequestRelay, ARefusalEndsTheStream) {
    RequestRelay relay({}, "::1");
    std::string forward = relayed(relay, "GET /a HTTP/1.1\r\n\r\nPOST /b HTTP/1.1\r\nContent-Length: x\r\n\r\nGET /c HTTP/1.1\r\n\r\n", 1000);
    ASSERT_TRUE(relay.refusal());
    EXPECT_EQ(relay.refusal()->status, 400);
    EXPECT_EQ(forward, "GET /a HTTP/1.1\r\nX-Photon-Client-Address: ::1\r\n\r\n");
    EXPECT_EQ(relay.requestsForwarded(), 1);
}

TEST(ResponseStream, EachResponseEndsWhereItsFramingSays) {
    ResponseStream responses;
    for (const char* method : {"GET", "HEAD", "POST", "GET"}) responses.expect(method);
    const std::string bytes =
        "HTTP/1.1 200 OK\r\nContent-Length: 5\r\n\r\nhello"
        "HTTP/1.1 200 OK\r\nContent-Length: 99\r\n\r\n"                 // HEAD: no body
        "HTTP/1.1 100 Continue\r\n\r\nHTTP/1.1 201 Created\r\nTransfer-Encoding: chunked\r\n\r\n3\r\nabc\r\n0\r\n\r\n"
        "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nTransfer-Encoding: chunked\r\n\r\n4\r\ndata\r\n";
    std::vector<size_t> outstandingAfter;
    for (char c : bytes) {
        ASSERT_TRUE(responses.consume(std::string_view(&c, 1)));
        outstandingAfter.push_back(responses.outstanding());
    }
    EXPECT_EQ(responses.outstanding(), 1u);  // the stream goes on
    EXPECT_EQ(std::count(outstandingAfter.begin(), outstandingAfter.end(), 3u) > 0, true);
    EXPECT_FALSE(responses.closesConnection());
    ASSERT_TRUE(responses.consume("0\r\n\r\n"));
    EXPECT_EQ(responses.outstanding(), 0u);
}

TEST(ResponseStream, ConnectionCloseAndUnframedBodies) {
    ResponseStream refused;
    refused.expect("POST");
    ASSERT_TRUE(refused.consume("HTTP/1.1 401 Unauthorized\r\nConnection: close\r\nContent-Length: 2\r\n\r\n{}"));
    EXPECT_EQ(refused.outstanding(), 0u);
    EXPECT_TRUE(refused.closesConnection());
    ResponseStream unframed;
    unframed.expect("GET");
    ASSERT_TRUE(unframed.consume("HTTP/1.1 200 OK\r\n\r\nuntil the end"));
    EXPECT_EQ(unframed.outstanding(), 1u);
    unframed.serverClosed();
    EXPECT_EQ(unframed.outstanding(), 0u);
    EXPECT_TRUE(unframed.closesConnection());
    ResponseStream garbage;
    garbage.expect("GET");
    EXPECT_FALSE(garbage.consume("SSH-2.0-OpenSSH\r\n\r\n"));
}

}  // namespace
}  // namespace photon::api
