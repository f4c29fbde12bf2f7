// Jobs have a name and labels from their submission and say when they last changed; the
// list filters by several statuses, a part of the name and labels, and pages with a cursor
// that stays right while jobs come and go.
#include "server_fixture.h"

namespace photon::test {
namespace {

class ListingTest : public ServerTest {
protected:
    json list(const std::string& query) {
        httplib::Result r = client().Get(("/api/v1/jobs" + query).c_str());
        EXPECT_TRUE(r);
        EXPECT_EQ(r->status, 200) << query << ": " << r->body;
        lastLink_ = r->get_header_value("Link");
        return json::parse(r->body);
    }
    static std::vector<std::string> ids(const json& page) {
        std::vector<std::string> out;
        for (const json& job : page["jobs"]) out.push_back(job["id"]);
        return out;
    }
    std::string lastLink_;
};

TEST_F(ListingTest, AJobHasTheNameAndLabelsItWasGiven) {
    startServer({"--workers", "0"});
    json job = json::parse(submit(smallScene(), "?name=Atrium%20final&label=project%3Datrium&label=draft")->body);
    EXPECT_EQ(job["name"], "Atrium final");
    EXPECT_EQ(job["labels"], json({"project=atrium", "draft"}));
    EXPECT_EQ(job["updated_at"], job["created_at"]);
    EXPECT_EQ(getJob(job["id"])["labels"], job["labels"]);
    // Multipart: form fields, and the name from the scene file's name when none is given.
    httplib::MultipartFormDataItems items{{"scene", smallScene().dump(), "kitchen.json", "application/json"},
                                          {"label", "project=kitchen", "", ""}};
    json fromFile = json::parse(client().Post("/api/v1/jobs", items)->body);
    EXPECT_EQ(fromFile["name"], "kitchen");
    EXPECT_EQ(fromFile["labels"], json({"project=kitchen"}));
    items.push_back({"name", "Kitchen, take 2", "", ""});
    EXPECT_EQ(json::parse(client().Post("/api/v1/jobs", items)->body)["name"], "Kitchen, take 2");
    EXPECT_EQ(json::parse(submit(smallScene())->body)["name"], "");  // a bare JSON body has no file name
    // A change moves updated_at on.
    json cancelled = json::parse(client().Post("/api/v1/jobs/" + job["id"].get<std::string>() + "/cancel")->body);
    EXPECT_EQ(cancelled["updated_at"], cancelled["finished_at"]);
}

TEST_F(ListingTest, BadNamesAndLabelsAre400) {
    startServer({"--workers", "0"});
    auto refused = [&](const std::string& query) {
        httplib::Result r = submit(smallScene(), query);
        EXPECT_EQ(r->status, 400) << query;
        return problemOf(r)["detail"].get<std::string>();
    };
    EXPECT_EQ(refused("?label=has%20space"), "label \"has space\": only letters, digits and . _ - : = / may be used");
    EXPECT_EQ(refused("?label="), "label \"\": must be 1 to 64 characters");
    EXPECT_EQ(refused("?name=" + std::string(201, 'n')), "name: 201 bytes, longer than 200");
    EXPECT_EQ(refused("?name=tab%09here"), "name: must be UTF-8 text without control characters");
    std::string many;
    for (int i = 0; i < 17; ++i) many += "&label=l" + std::to_string(i);
    EXPECT_EQ(refused("?" + many.substr(1)), "label: 17 labels, more than 16");
    EXPECT_EQ(json::parse(client().Get("/api/v1/jobs")->body)["total"], 0);
}

TEST_F(ListingTest, TheListFiltersBySeveralStatusesANameAndLabels) {
    startServer({"--workers", "0"});
    std::string a = submitOk(smallScene(), "?name=Atrium%20draft&label=project%3Datrium&label=draft");
    std::string b = submitOk(smallScene(), "?name=atrium%20final&label=project%3Datrium");
    std::string c = submitOk(smallScene(), "?name=Kitchen&label=project%3Dkitchen&label=draft");
    ASSERT_EQ(client().Post("/api/v1/jobs/" + b + "/cancel")->status, 200);
    EXPECT_EQ(ids(list("?status=queued")), (std::vector<std::string>{c, a}));
    EXPECT_EQ(ids(list("?status=queued,cancelled")), (std::vector<std::string>{c, b, a}));
    EXPECT_EQ(ids(list("?status=cancelled&status=completed")), (std::vector<std::string>{b}));
    EXPECT_EQ(ids(list("?name=ATRIUM")), (std::vector<std::string>{b, a}));
    EXPECT_EQ(ids(list("?label=draft")), (std::vector<std::string>{c, a}));
    EXPECT_EQ(ids(list("?label=draft&label=project%3Datrium")), (std::vector<std::string>{a}));
    json none = list("?status=queued&name=final");
    EXPECT_EQ(none["total"], 0);
    EXPECT_EQ(none["next_cursor"], nullptr);
    httplib::Result bad = client().Get("/api/v1/jobs?status=queued,stalled");
    EXPECT_EQ(bad->status, 400);
    EXPECT_EQ(problemOf(bad)["detail"],
              "query parameter status: expected queued, running, paused, completed, failed or cancelled, got \"stalled\"");
}

TEST_F(ListingTest, ACursorPagesThroughEveryJobOnceWhileJobsComeAndGo) {
    startServer({"--workers", "0"});
    std::vector<std::string> submitted;
    for (int i = 0; i < 5; ++i) submitted.push_back(submitOk(smallScene(), "?label=batch"));
    json first = list("?label=batch&limit=2");
    EXPECT_EQ(ids(first), (std::vector<std::string>{submitted[4], submitted[3]}));
    ASSERT_TRUE(first["next_cursor"].is_string());
    const std::string cursor = first["next_cursor"];
    EXPECT_EQ(lastLink_, "</api/v1/jobs?label=batch&limit=2&cursor=" + cursor + ">; rel=\"next\"");
    // Between pages a job is submitted and a listed one deleted: neither shifts the next page.
    submitOk(smallScene(), "?label=batch");
    ASSERT_EQ(client().Post("/api/v1/jobs/" + submitted[4] + "/cancel")->status, 200);
    ASSERT_EQ(client().Delete(("/api/v1/jobs/" + submitted[4]).c_str())->status, 204);
    json second = list("?label=batch&limit=2&cursor=" + cursor);
    EXPECT_EQ(ids(second), (std::vector<std::string>{submitted[2], submitted[1]}));
    json last = list("?label=batch&limit=2&cursor=" + second["next_cursor"].get<std::string>());
    EXPECT_EQ(ids(last), (std::vector<std::string>{submitted[0]}));
    EXPECT_EQ(last["next_cursor"], nullptr);
    EXPECT_EQ(lastLink_, "");
    httplib::Result bad = client().Get("/api/v1/jobs?cursor=abc");
    EXPECT_EQ(bad->status, 400);
    EXPECT_EQ(client().Get(("/api/v1/jobs?offset=1&cursor=" + cursor).c_str())->status, 400);
}

}  // namespace
}  // namespace photon::test
