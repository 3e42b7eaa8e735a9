// POV-Ray render quality +Q6 on the scene of quality.inc (renderer/tracer.hpp Quality).
// switches: +Q6
#include "quality.inc"
