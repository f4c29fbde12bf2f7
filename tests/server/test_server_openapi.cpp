// api/openapi.yaml documents exactly the routes the server registers (the route table,
// as printed by --print-routes), with the same methods.
#include <fstream>
#include <set>
#include "server_fixture.h"

namespace photon::test {
namespace {

using RouteSet = std::set<std::string>;  // "GET /api/v1/jobs/{id}"

RouteSet registeredRoutes() {
    RouteSet routes;
    std::istringstream lines(runServerBinary({"--print-routes"}));
    std::string line;
    while (std::getline(lines, line))
        if (!line.empty()) routes.insert(line);
    return routes;
}

// A line scan, no YAML library: under the top-level `paths:` key, path keys are indented
// two spaces and operations (get/post/delete/...) four.
RouteSet documentedRoutes() {
    std::ifstream in(std::string(PHOTON_SOURCE_DIR) + "/api/openapi.yaml");
    EXPECT_TRUE(in) << "api/openapi.yaml missing";
    RouteSet routes;
    std::string line, path;
    bool inPaths = false;
    const std::set<std::string> methods{"get", "put", "post", "delete", "patch", "head", "options"};
    while (std::getline(in, line)) {
        if (!line.empty() && line[0] != ' ' && line[0] != '#') inPaths = line.rfind("paths:", 0) == 0;
        if (!inPaths) continue;
        if (line.rfind("  /", 0) == 0 && line.back() == ':') {
            path = line.substr(2, line.size() - 3);
            if (path.size() > 1 && path.front() == '"') path = path.substr(1, path.size() - 2);
        } else if (line.rfind("    ", 0) == 0 && line[4] != ' ' && line.back() == ':') {
            std::string key = line.substr(4, line.size() - 5);
            if (methods.count(key)) {
                for (char& ch : key) ch = char(std::toupper(static_cast<unsigned char>(ch)));
                routes.insert(key + " " + path);
            }
        }
    }
    return routes;
}

TEST(OpenApi, DocumentsExactlyTheRegisteredRoutes) {
    RouteSet registered = registeredRoutes();
    RouteSet documented = documentedRoutes();
    ASSERT_FALSE(registered.empty());
    for (const std::string& r : registered) EXPECT_TRUE(documented.count(r)) << r << " is not in openapi.yaml";
    for (const std::string& r : documented) EXPECT_TRUE(registered.count(r)) << r << " is documented but not served";
}

}  // namespace
}  // namespace photon::test
