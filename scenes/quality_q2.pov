// POV-Ray render quality +Q2 on the scene of quality.inc (renderer/tracer.hpp Quality).
// switches: +Q2
#include "quality.inc"
