// The lock lives with the other platform code (platform/shared_mutex.h); this name stays for the
// headers that still include it (level/level.h, world/*.h).
#pragma once

#include "platform/shared_mutex.h"
