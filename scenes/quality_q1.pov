// POV-Ray render quality +Q1 on the scene of quality.inc (renderer/tracer.hpp Quality).
// switches: +Q1
#include "quality.inc"
