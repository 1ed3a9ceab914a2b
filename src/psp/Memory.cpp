// SPDX-License-Identifier: Apache-2.0
#include "psp/Memory.h"

#include <cstring>

namespace flarekit::psp {

Memory::Memory(MemoryModel model) : m_model(model), m_vram(kVramSize, 0), m_ram(kRamSize, 0) {
    if (model == MemoryModel::SplitFramebuffers) {
        m_hostVram.assign(kVramSize, 0);
        m_rendered.assign(kVramSize, false);
    }
}

bool Memory::valid(std::uint32_t address, std::uint32_t size) const {
    const std::uint64_t end = std::uint64_t(address) + size;
    return (address >= kVramBase && end <= std::uint64_t(kVramBase) + kVramSize) ||
           (address >= kRamBase && end <= std::uint64_t(kRamBase) + kRamSize);
}

std::uint8_t* Memory::plain(std::uint32_t address) {
    if (address >= kVramBase && address - kVramBase < kVramSize)
        return &m_vram[address - kVramBase];
    if (address >= kRamBase && address - kRamBase < kRamSize) return &m_ram[address - kRamBase];
    return nullptr;
}
const std::uint8_t* Memory::plain(std::uint32_t address) const {
    return const_cast<Memory*>(this)->plain(address);
}

std::uint8_t Memory::read8(std::uint32_t address) const {
    const std::uint8_t* p = plain(address);
    return p ? *p : 0;
}
std::uint16_t Memory::read16(std::uint32_t address) const {
    return std::uint16_t(read8(address) | read8(address + 1) << 8);
}
std::uint32_t Memory::read32(std::uint32_t address) const {
    return std::uint32_t(read16(address)) | std::uint32_t(read16(address + 2)) << 16;
}
void Memory::write8(std::uint32_t address, std::uint8_t value) {
    if (std::uint8_t* p = plain(address)) *p = value;
}
void Memory::write16(std::uint32_t address, std::uint16_t value) {
    write8(address, std::uint8_t(value)), write8(address + 1, std::uint8_t(value >> 8));
}
void Memory::write32(std::uint32_t address, std::uint32_t value) {
    write16(address, std::uint16_t(value)), write16(address + 2, std::uint16_t(value >> 16));
}
void Memory::writeBytes(std::uint32_t address, const void* data, std::size_t size) {
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    for (std::size_t i = 0; i < size; ++i) write8(address + std::uint32_t(i), bytes[i]);
}

std::uint8_t Memory::gpuRead8(std::uint32_t address) const {
    if (m_model == MemoryModel::SplitFramebuffers && address >= kVramBase &&
        address - kVramBase < kVramSize && m_rendered[address - kVramBase])
        return m_hostVram[address - kVramBase];
    return read8(address);
}
std::uint16_t Memory::gpuRead16(std::uint32_t address) const {
    return std::uint16_t(gpuRead8(address) | gpuRead8(address + 1) << 8);
}
std::uint32_t Memory::gpuRead32(std::uint32_t address) const {
    return std::uint32_t(gpuRead16(address)) | std::uint32_t(gpuRead16(address + 2)) << 16;
}
void Memory::gpuWrite8(std::uint32_t address, std::uint8_t value) {
    if (m_model == MemoryModel::SplitFramebuffers && address >= kVramBase &&
        address - kVramBase < kVramSize) {
        m_hostVram[address - kVramBase] = value;
        m_rendered[address - kVramBase] = true;
        return;
    }
    write8(address, value);
}
void Memory::gpuWrite16(std::uint32_t address, std::uint16_t value) {
    gpuWrite8(address, std::uint8_t(value)), gpuWrite8(address + 1, std::uint8_t(value >> 8));
}
void Memory::gpuWrite32(std::uint32_t address, std::uint32_t value) {
    gpuWrite16(address, std::uint16_t(value)), gpuWrite16(address + 2, std::uint16_t(value >> 16));
}

}  // namespace flarekit::psp
