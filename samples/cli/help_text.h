// What `navlink --help` and `navlink COMMAND --help` print.
#pragma once

namespace nl::cli {

extern const char* const kMainHelp;
extern const char* const kGenerateHelp;
extern const char* const kPathHelp;
extern const char* const kBakeHelp;
extern const char* const kInfoHelp;
extern const char* const kDemoHelp;
extern const char* const kSimulateHelp;
extern const char* const kLevelHelp;

}  // namespace nl::cli
