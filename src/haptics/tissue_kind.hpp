#pragma once
// What an instrument touches, for the force model's parameters (eq. 17-19 per tissue type, as
// the paper's 2.4.4 asks), and the electrocautery's mode.
#include <cstdint>

namespace imasim::haptics {

enum class TissueKind : std::uint8_t { fascia, fat, ima, heart, chest_wall };
inline constexpr std::size_t kTissueKinds = 5;

enum class CauteryMode : std::uint8_t { off, cut, coag };

const char* tissue_kind_name(TissueKind kind);

}  // namespace imasim::haptics
