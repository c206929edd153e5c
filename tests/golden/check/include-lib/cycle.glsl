// Includes itself: the include fails past 64 levels instead of never ending.
#include "cycle.glsl"
