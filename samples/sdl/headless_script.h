// The viewer without a display: a scripted sequence of frames written as PNG files, each one a step
// a user would take in the window (clicks turned into the same picks, key presses into the same
// state changes), so the interactive code paths run in tests and on servers.
#pragma once

#include <string>

#include "scene.h"
#include "viewer_session.h"

namespace nl::picture {

// Writes DIR/frame_NN.png for every step and prints one line per frame, with each agent's outcome.
// Returns the exit status: 1 if a scripted click found no surface or picked another place than the
// one drawn under it (an unreachable destination is an outcome, not a failure).
int run_headless_script(ViewerSession& session, ViewSettings view, const std::string& dir);

// The agents' trip from the start to the destination the host gave (navlink-viewer --from --to; or
// with tile streaming on, to the level's own destination), its frames written as above, with a frame
// for each of the first few changes of the tiles streaming, and a line saying how many tiles were
// loaded at most and how many were removed and added. Returns 0 when every chosen agent arrived, 1
// when one did not.
int run_headless_trip(ViewerSession& session, const ViewSettings& view, const std::string& dir);

}  // namespace nl::picture
