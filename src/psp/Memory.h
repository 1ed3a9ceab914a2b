// SPDX-License-Identifier: Apache-2.0
// The PSP address space the Burnout trick needs: 2 MiB of VRAM at 0x04000000 and 4 MiB of main
// RAM at 0x08000000, little-endian. "Memory is memory" (burnout-dominator-psp-lens-flare.md):
// a framebuffer, a depth buffer, a texture and a CLUT are only addresses, so a render target
// can alias a palette. The naive model (an emulator that keeps render targets in host-side
// copies) is the second half of this class: GE writes then land in a shadow, texture reads see
// the shadow, but CLUT loads read plain memory and never see what was rendered.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace flarekit::psp {

constexpr std::uint32_t kVramBase = 0x04000000, kVramSize = 2u << 20;  // PSP VRAM
constexpr std::uint32_t kRamBase = 0x08000000,
                        kRamSize = 4u << 20;  // enough user RAM for the lists

enum class MemoryModel {
    Unified,           //!< the hardware: the GE reads and writes the one memory
    SplitFramebuffers  //!< a naive emulator: rendering goes to host framebuffers, CLUT loads miss
                       //!< it
};

class Memory {
  public:
    explicit Memory(MemoryModel model = MemoryModel::Unified);
    MemoryModel model() const { return m_model; }

    //! True when [address, address + size) is mapped.
    bool valid(std::uint32_t address, std::uint32_t size) const;

    // What the CPU and the GE's CLUT loader see: plain memory. Out-of-range reads return 0
    // and writes are dropped; the GE checks ranges before it uses these (valid()).
    std::uint8_t read8(std::uint32_t address) const;
    std::uint16_t read16(std::uint32_t address) const;
    std::uint32_t read32(std::uint32_t address) const;
    void write8(std::uint32_t address, std::uint8_t value);
    void write16(std::uint32_t address, std::uint16_t value);
    void write32(std::uint32_t address, std::uint32_t value);
    void writeBytes(std::uint32_t address, const void* data, std::size_t size);

    // What the GE's pixel pipeline, texture unit and block transfers see. Unified: the same
    // memory. SplitFramebuffers: writes go to the host copy of VRAM and mark it; reads of
    // marked bytes come from there.
    std::uint8_t gpuRead8(std::uint32_t address) const;
    std::uint16_t gpuRead16(std::uint32_t address) const;
    std::uint32_t gpuRead32(std::uint32_t address) const;
    void gpuWrite8(std::uint32_t address, std::uint8_t value);
    void gpuWrite16(std::uint32_t address, std::uint16_t value);
    void gpuWrite32(std::uint32_t address, std::uint32_t value);

  private:
    std::uint8_t* plain(std::uint32_t address);
    const std::uint8_t* plain(std::uint32_t address) const;

    MemoryModel m_model;
    std::vector<std::uint8_t> m_vram, m_ram;
    std::vector<std::uint8_t> m_hostVram;  //!< SplitFramebuffers: the host framebuffers' bytes
    std::vector<bool> m_rendered;          //!< SplitFramebuffers: VRAM bytes the GE has written
};

}  // namespace flarekit::psp
