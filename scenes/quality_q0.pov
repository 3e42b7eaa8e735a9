// POV-Ray render quality +Q0 on the scene of quality.inc (renderer/tracer.hpp Quality).
// switches: +Q0
#include "quality.inc"
