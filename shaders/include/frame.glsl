// Per-frame constants shared by every pass (layout declared once in bindings.h).
#include "include/bindings.h"

layout(std140, binding = SSAO_UBO_FRAME) uniform FrameBlock { FrameConstants_ frame; };
