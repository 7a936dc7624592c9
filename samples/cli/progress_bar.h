// A one-line progress bar for a navmesh build or a link generation, redrawn in place; only when stdout is a terminal, so
// logs and pipes get the report alone.
#pragma once

#include <navlink/navlink.h>

namespace nl::cli {

class ProgressBar {
public:
    ProgressBar();   // decides once whether stdout is a terminal
    ~ProgressBar();  // ends the line if one was drawn

    // An nl_progress_fn; `user` is the ProgressBar. Never cancels.
    static int32_t callback(void* user, float fraction, const char* stage);
    bool enabled() const { return enabled_; }

private:
    void draw(float fraction, const char* stage);
    bool enabled_;
    bool drawn_ = false;
};

}  // namespace nl::cli
