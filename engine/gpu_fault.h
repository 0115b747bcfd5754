// Faults injected on purpose into the GPU path's image, so that a driver
// team can prove its parity gate trips on a real fault and passes a
// harmless one (docs/parity.md, "Proving the gate"). FACET_FAULT names one;
// for QA only: a render with a fault says so in its device's name.
#pragma once

#include <optional>
#include <string>

#include "engine/image/image.h"

namespace facet {

enum class GpuFault {
  BeautyBias,     // every beauty channel 1% high: a constant or rounding mode wrong throughout
  DroppedTile,    // a 16 x 16 block of beauty black: a dispatch that never ran
  ShiftedPixel,   // every AOV one pixel to the right: a stage's output written one pixel off
  FlippedNormal,  // one covered pixel's shading normal reversed: one bit of a kernel's result
  BeautyUlp,      // every beauty channel one float ulp high: within any tolerance, which must pass
};

inline constexpr const char* kGpuFaultNames = "beauty-bias, dropped-tile, shifted-pixel, flipped-normal, beauty-ulp";

// FACET_FAULT's fault; none where it is unset or empty. Throws
// std::invalid_argument "FACET_FAULT '<value>': expected one of: ..." for
// any other value.
std::optional<GpuFault> gpuFaultFromEnvironment();

const char* toString(GpuFault fault);

void injectFault(GpuFault fault, Image& image);

}  // namespace facet
