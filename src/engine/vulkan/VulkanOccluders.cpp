// SPDX-License-Identifier: Apache-2.0
// VulkanOccluders: a scene's objects drawn into sun-map tiles by the Vulkan occluder callback
// (vk_occluder.vert/.frag), as SceneOccluders does on GL.
#include <cstring>
#include <tuple>

#include "engine/vulkan/VulkanHostImpl.h"
#include "flarekit_exported_shaders.h"
#include "scene/SceneMesh.h"

namespace flarekit::vk {

struct VulkanOccluders::Impl {
    const VulkanHost* host = nullptr;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline opaque = VK_NULL_HANDLE, closed = VK_NULL_HANDLE, open = VK_NULL_HANDLE;
    Buffer opaqueMesh, translucentMesh;
    std::uint32_t opaqueCount = 0;
    std::vector<TranslucentRange> ranges;

    const Device& d() const { return host->device(); }
    Result<VkPipeline> pipeline(VkShaderModule vert, VkShaderModule frag, bool multiply,
                                bool frontFacesOnly) const;
};

VulkanOccluders::VulkanOccluders(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}

VulkanOccluders::~VulkanOccluders() {
    const Device& d = m->d();
    for (VkPipeline p : {m->opaque, m->closed, m->open})
        if (p) d.api.vkDestroyPipeline(d.device, p, nullptr);
    if (m->layout) d.api.vkDestroyPipelineLayout(d.device, m->layout, nullptr);
    d.destroy(m->opaqueMesh);
    d.destroy(m->translucentMesh);
}

Result<VkPipeline> VulkanOccluders::Impl::pipeline(VkShaderModule vert, VkShaderModule frag,
                                                   bool multiply, bool frontFacesOnly) const {
    PipelineDesc desc;
    desc.vertex = vert;
    desc.fragment = frag;
    desc.vertexStride = 12;
    desc.cull = frontFacesOnly ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
    desc.blend = multiply ? PipelineDesc::Blend::Multiply : PipelineDesc::Blend::None;
    desc.color = FK_VULKAN_SUN_MAP_FORMAT;
    desc.layout = layout;
    return d().makePipeline(desc);
}

Result<std::unique_ptr<VulkanOccluders>> VulkanOccluders::create(const VulkanHost& host,
                                                                 const Scene& scene) {
    auto m = std::make_unique<Impl>();
    m->host = &host;
    const Device& d = host.device();
    const VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                    68};
    auto layoutInfo =
        make<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    layoutInfo.pushConstantRangeCount = 1;
    layoutInfo.pPushConstantRanges = &range;
    if (Status s = check(d.api.vkCreatePipelineLayout(d.device, &layoutInfo, nullptr, &m->layout),
                         "vkCreatePipelineLayout");
        !s)
        return s.error();
    auto vert = d.makeShader(exported::vk_occluder_vert_spv, exported::vk_occluder_vert_spv_size);
    if (!vert) return vert.error();
    auto frag = d.makeShader(exported::vk_occluder_frag_spv, exported::vk_occluder_frag_spv_size);
    if (!frag) {
        d.api.vkDestroyShaderModule(d.device, *vert, nullptr);
        return frag.error();
    }
    auto opaque = m->pipeline(*vert, *frag, false, false);
    auto closed = m->pipeline(*vert, *frag, true, true);
    auto open = m->pipeline(*vert, *frag, true, false);
    d.api.vkDestroyShaderModule(d.device, *vert, nullptr);
    d.api.vkDestroyShaderModule(d.device, *frag, nullptr);
    for (auto [made, out] : {std::pair{&opaque, &m->opaque}, std::pair{&closed, &m->closed},
                             std::pair{&open, &m->open}}) {
        if (!*made) return made->error();
        *out = **made;
    }
    const Scene clear = translucentObjects(scene);
    m->ranges = translucentRanges(clear);
    for (auto [objects, out, count] :
         {std::tuple{opaqueObjects(scene), &m->opaqueMesh, &m->opaqueCount},
          std::tuple{clear, &m->translucentMesh, static_cast<std::uint32_t*>(nullptr)}}) {
        std::vector<float> xyz;
        for (const MeshVertex& v : buildSceneMesh(objects))
            xyz.insert(xyz.end(), v.position, v.position + 3);
        if (count) *count = std::uint32_t(xyz.size() / 3);
        if (xyz.empty()) continue;
        auto b = d.makeBuffer(VkDeviceSize(xyz.size() * sizeof(float)),
                              VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, true);
        if (!b) return b.error();
        *out = *b;
        std::memcpy(out->mapped, xyz.data(), xyz.size() * sizeof(float));
    }
    return std::unique_ptr<VulkanOccluders>(new VulkanOccluders(std::move(m)));
}

void VulkanOccluders::draw(void* user, VkCommandBuffer cmd, int, int, const float* viewProjection) {
    auto* self = static_cast<VulkanOccluders*>(user);
    ++self->calls;
    const Impl& m = *self->m;
    const Api& a = m.d().api;
    const HostApi& h = m.host->m->h;
    struct {
        float viewProjection[16];
        float keep;
    } push{};
    std::memcpy(push.viewProjection, viewProjection, sizeof push.viewProjection);
    constexpr VkShaderStageFlags kStages =
        VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    const VkDeviceSize offset = 0;
    if (m.opaqueCount > 0) {
        a.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m.opaque);
        h.vkCmdPushConstants(cmd, m.layout, kStages, 0, sizeof push, &push);
        h.vkCmdBindVertexBuffers(cmd, 0, 1, &m.opaqueMesh.buffer, &offset);
        a.vkCmdDraw(cmd, m.opaqueCount, 1, 0, 0);
    }
    if (m.ranges.empty()) return;
    h.vkCmdBindVertexBuffers(cmd, 0, 1, &m.translucentMesh.buffer, &offset);
    for (const TranslucentRange& r : m.ranges) {
        a.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, r.closed ? m.closed : m.open);
        push.keep = 1.f - r.opacity;
        h.vkCmdPushConstants(cmd, m.layout, kStages, 0, sizeof push, &push);
        a.vkCmdDraw(cmd, std::uint32_t(r.count), 1, std::uint32_t(r.first), 0);
    }
}

}  // namespace flarekit::vk
