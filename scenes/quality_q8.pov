// POV-Ray render quality +Q8 on the scene of quality.inc (renderer/tracer.hpp Quality).
// switches: +Q8
#include "quality.inc"
