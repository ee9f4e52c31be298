// incident_replay BAG: every decision of an incident bag that the gate's rules judged, judged
// again by the same ROS-free code and compared bit for bit (doc/incidents.md, "Replay").
// incident_report --replay runs it.

#include "ellipse_collision/app/incident_replay.h"

#include <iostream>
#include <string>

#include "ellipse_collision/ros/incident_bag.h"

int main(int argc, char** argv) {
  namespace ec = ellipse_collision;
  if (argc != 2 || std::string(argv[1]).rfind('-', 0) == 0) {
    std::cerr << "usage: incident_replay BAG\n"
                 "Judges each recorded decision of the incident bag again and prints one line per "
                 "decision not reproduced and a summary; exit 0 when all are, 1 when one is not "
                 "(or none was judged by the gate's rules), 2 when the bag cannot be replayed.\n";
    return 2;
  }
  ec::ReplayInput input;
  const std::string error = ec::readIncidentBag(argv[1], &input);
  if (!error.empty()) {
    std::cerr << "incident_replay: " << error << "\n";
    return 2;
  }
  const ec::app::ReplayReport report = ec::app::replayIncident(input.decisions, input.settings);
  for (const ec::app::ReplayMismatch& mismatch : report.mismatches) {
    std::cout << ec::app::describeMismatch(mismatch) << "\n";
  }
  std::cout << ec::app::replaySummary(report) << std::endl;
  return report.reproduced() ? 0 : 1;
}
