#pragma once
/// A handshake for deterministic interrupt tests, off unless its environment
/// variables are set: with F2_TEST_PAUSE_AFTER_FRAMES=N and
/// F2_TEST_PAUSE_FILE=PATH, `f2 render` creates PATH once N frames of an
/// animation are finished, then waits until SIGINT or SIGTERM arrives. A test
/// waits for PATH and sends the signal: it always lands mid-animation, on a
/// loaded machine as on an idle one, with no sleep to tune.

namespace f2::cli {

/// Called each time `framesDone` frames are finished; pauses as described
/// above when `framesDone` is the requested N.
void pauseForTestAfter(int framesDone);

}  // namespace f2::cli
