// An answer given to a request before anything is done with it: its status and reason.
#pragma once
#include <string>

namespace photon::api {

struct Refusal {
    int status = 0;
    std::string message;
};

}  // namespace photon::api
