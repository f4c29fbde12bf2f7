// Route handlers, one file per resource (routes_*.cpp); the table in routes.cpp wires them.
#pragma once
#include "api/routes.h"

namespace photon::api {

// routes_jobs.cpp
void createJob(RouteContext&, const httplib::Request&, httplib::Response&, const httplib::ContentReader&);
void listJobs(RouteContext&, const httplib::Request&, httplib::Response&);
void getJob(RouteContext&, const httplib::Request&, httplib::Response&);
void cancelJob(RouteContext&, const httplib::Request&, httplib::Response&);
void updateJob(RouteContext&, const httplib::Request&, httplib::Response&);
void cloneJob(RouteContext&, const httplib::Request&, httplib::Response&);
void getScene(RouteContext&, const httplib::Request&, httplib::Response&);
void getLog(RouteContext&, const httplib::Request&, httplib::Response&);
void getProgressHistory(RouteContext&, const httplib::Request&, httplib::Response&);
void pauseJob(RouteContext&, const httplib::Request&, httplib::Response&);
void resumeJob(RouteContext&, const httplib::Request&, httplib::Response&);
void continueJob(RouteContext&, const httplib::Request&, httplib::Response&);
void deleteJob(RouteContext&, const httplib::Request&, httplib::Response&);
// routes_images.cpp
void getImage(RouteContext&, const httplib::Request&, httplib::Response&);
void streamImages(RouteContext&, const httplib::Request&, httplib::Response&);
// routes_events.cpp
void jobEvents(RouteContext&, const httplib::Request&, httplib::Response&);
void serviceEvents(RouteContext&, const httplib::Request&, httplib::Response&);
// routes_system.cpp
void health(RouteContext&, const httplib::Request&, httplib::Response&);
void info(RouteContext&, const httplib::Request&, httplib::Response&);
void listWorkers(RouteContext&, const httplib::Request&, httplib::Response&);
void metrics(RouteContext&, const httplib::Request&, httplib::Response&);
void homePage(RouteContext&, const httplib::Request&, httplib::Response&);
// routes_session.cpp
void startSession(RouteContext&, const httplib::Request&, httplib::Response&);
void endSession(RouteContext&, const httplib::Request&, httplib::Response&);

}  // namespace photon::api
