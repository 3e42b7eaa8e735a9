// POV-Ray render quality +Q5 on the scene of quality.inc (renderer/tracer.hpp Quality).
// switches: +Q5
#include "quality.inc"
