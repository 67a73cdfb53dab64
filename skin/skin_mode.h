// How a skin hit is simulated: the exact HyLIoS walk (skin/skin_walk.h) or a sample from the
// tabulated exit distribution (skin/exit_table.h, the fast path). Named "walk" / "table" in scene
// files (`skin_mode`) and on the command line (`--skin-model`).
#pragma once
#include "skin/core/enum_names.h"

namespace hylios::skin {

enum class SkinMode { Walk, Table };

inline constexpr EnumNames<SkinMode, 2> kSkinModeNames{
    {{SkinMode::Walk, "walk"}, {SkinMode::Table, "table"}}};

}  // namespace hylios::skin
