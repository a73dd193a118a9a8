// Settings, whole: the shared blocks (base/shared_settings.h) and one member per technique
// (techniques/technique_settings.h, where the techniques' own settings live).
#pragma once
#include "techniques/technique_settings.h"
