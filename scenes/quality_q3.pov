// POV-Ray render quality +Q3 on the scene of quality.inc (renderer/tracer.hpp Quality).
// switches: +Q3
#include "quality.inc"
