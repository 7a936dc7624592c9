#include "progress_bar.h"

#include <cstdio>
#include <string>
#include <unistd.h>

namespace nl::cli {

ProgressBar::ProgressBar() : enabled_(isatty(STDOUT_FILENO) == 1) {}

ProgressBar::~ProgressBar() {
    if (drawn_) {
        std::printf("\r\033[K");  // clear the bar: the report follows on a clean line
        std::fflush(stdout);
    }
}

int32_t ProgressBar::callback(void* user, float fraction, const char* stage) {
    auto* bar = static_cast<ProgressBar*>(user);
    if (bar->enabled_) bar->draw(fraction, stage);
    return 1;
}

void ProgressBar::draw(float fraction, const char* stage) {
    const int width = 30;
    const int filled = static_cast<int>(fraction * width + 0.5f);
    std::string bar(static_cast<size_t>(filled), '#');
    bar.append(static_cast<size_t>(width - filled), '.');
    std::printf("\r\033[K  [%s] %3.0f%%  %s", bar.c_str(), 100.0f * fraction, stage ? stage : "");
    std::fflush(stdout);
    drawn_ = true;
}

}  // namespace nl::cli
