// Floats written for people and for JSON: 0.1, not 0.10000000149011612.
#pragma once

namespace nl {

// The shortest decimal (as a double) that reads back as `v`.
double shortest_decimal(float v);

}  // namespace nl
