// The viewer in a window: click to set the destination (shift-click or right-click: the start), keys
// to switch agent and toggle layers. Paths are planned in the background and drawn when ready.
#pragma once

#include "scene.h"
#include "viewer_session.h"

namespace nl::picture {

// Help shown on the console when the window opens.
extern const char* const kViewerKeys;

// Runs until the window is closed or Escape/Q. Returns the exit status. SDL video is initialised.
int run_interactive_viewer(ViewerSession& session, ViewSettings view);

}  // namespace nl::picture
