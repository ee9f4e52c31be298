#pragma once

namespace ellipse_collision::app {

/// Why a request was not answered as asked, as a type the edges can act on (a log level, a
/// diagnostics level) instead of a prefix of the message text (box2d's typed outcomes).
enum class ErrorKind {
  None,            ///< answered
  InvalidRequest,  ///< the request broke a field, name or size rule: the caller's to fix
  FrameUnavailable,  ///< a frame the request needs has no (fresh) transform
  NotPersisted,    ///< the change is in memory, but the obstacle store could not be written
  Internal,        ///< a request that passed validation was refused by the core: a bug
};

}  // namespace ellipse_collision::app
