// POV-Ray render quality +Q9 on the scene of quality.inc (renderer/tracer.hpp Quality).
// switches: +Q9
#include "quality.inc"
