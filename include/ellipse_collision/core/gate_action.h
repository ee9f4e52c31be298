#pragma once

namespace ellipse_collision::core {

/// What the velocity gate does with a command. gateTwist() answers the first four; the others
/// are the application's (the node's ~gate_state shows every one).
enum class GateAction {
  Pass,        ///< sent as given (scale 1)
  Slow,        ///< scaled by 0 < scale < 1
  Stop,        ///< scale 0
  Escape,      ///< some pair is close now; the command (scaled by 0 < scale <= 1) moves them apart
  Timeout,     ///< no command within cmd_vel_timeout: one zero sent
  Incomplete,  ///< not every ellipse placed from fresh data (on_incomplete: stop)
  Disabled,    ///< the gate is off: sent as given
};

/// "PASS", "SLOW", "STOP", "ESCAPE", "TIMEOUT", "INCOMPLETE", "DISABLED"; "STOP" for a value
/// outside the enum.
const char* toString(GateAction action);

/// The one rule of which actions stop the robot (STOP, TIMEOUT, INCOMPLETE, and a value outside
/// the enum): the counters, the log and the markers all ask it.
bool stops(GateAction action);

}  // namespace ellipse_collision::core
