// The viewer's scripted frames with the moving platforms (--platforms without a display, or with
// --headless): the passengers go from the apron to their destinations at 60 steps a second while
// the platforms move, and a frame is written at the first of each thing a platform makes happen.
#pragma once

#include <string>

#include "scene.h"
#include "viewer_session.h"

namespace nl::picture {

// Writes DIR/frame_NN.png: the start; then the first time a passenger waits for a platform that is
// away, waits on one for its way off, rides a shuttle or lift half-way, or is half-way off one (each
// once per platform and kind; what happens in the same step shares a frame); and when every
// passenger has stopped. Prints one line per frame: what it shows, the agents, where each platform
// is. Returns 0 when every passenger arrived, else 1.
int run_platforms_script(ViewerSession& session, ViewSettings view, const std::string& dir);

}  // namespace nl::picture
