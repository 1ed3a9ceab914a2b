// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the PSP Graphics Engine on arbitrary display lists (the input is the list,
// loaded at the start of RAM, run on both memory models) and the emulated Burnout frame on an
// arbitrary occluder mask (the input's bytes tiled over 480x272, the sun from its first bytes).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "FuzzLimits.h"
#include "flarekit/Psp.h"
#include "psp/Ge.h"
#include "psp/Memory.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace flarekit::psp;
    flarekit::fuzz::setLimits();
    if (size < 4) return 0;
    for (MemoryModel model : {MemoryModel::Unified, MemoryModel::SplitFramebuffers}) {
        Memory memory(model);
        const std::size_t listBytes = std::min<std::size_t>(size, kRamSize / 2) & ~std::size_t(3);
        memory.writeBytes(kRamBase, data, listBytes);
        // END after the input: a list ends where the input does, not after a million NOPs of
        // empty RAM (a list without END is still tested: a JUMP can leave the input).
        memory.write32(kRamBase + std::uint32_t(listBytes), 0x0Cu << 24);
        Ge ge(memory);
        (void)ge.run(kRamBase);
    }
    // One input in eight also runs the whole emulated frame (150 ms under ASan); the others
    // exercise the GE alone, hundreds of times faster.
    if ((data[3] & 0x70) != 0) return 0;
    PspFrameInput input;
    input.occluders.resize(std::size_t(kScreenWidth) * kScreenHeight);
    for (std::size_t i = 0; i < input.occluders.size(); ++i) input.occluders[i] = data[i % size];
    input.sunX = int(data[0]) * 2 - 16;  // [-16, 494]: in and out of the screen
    input.sunY = int(data[1]) + int(data[2]) / 8 - 16;
    input.naive = data[3] & 1;
    (void)runPspFrame(data[3] & 2 ? PspTrick::RidgeRacer : PspTrick::Burnout, input);
    return 0;
}
