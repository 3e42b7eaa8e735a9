// POV-Ray render quality +Q4 on the scene of quality.inc (renderer/tracer.hpp Quality).
// switches: +Q4
#include "quality.inc"
