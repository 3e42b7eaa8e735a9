// POV-Ray render quality +Q7 on the scene of quality.inc (renderer/tracer.hpp Quality).
// switches: +Q7
#include "quality.inc"
