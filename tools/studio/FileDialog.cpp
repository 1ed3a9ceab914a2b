// SPDX-License-Identifier: Apache-2.0
#include "FileDialog.h"

#include <imgui.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

namespace flarekit::studio {

namespace fs = std::filesystem;

void FileDialog::open(const std::string& title, std::vector<std::string> extensions, bool saving,
                      std::function<void(const std::string&)> chosen) {
    m_open = true, m_justOpened = true, m_saving = saving;
    m_title = title;
    m_extensions = std::move(extensions);
    m_chosen = std::move(chosen);
    std::error_code ec;
    if (m_folder.empty()) m_folder = fs::current_path(ec).string();
    m_name[0] = '\0';
    list();
}

void FileDialog::list() {
    m_entries.clear();
    std::error_code ec;
    for (fs::directory_iterator it(m_folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        const bool folder = it->is_directory(ec);
        std::string ext = it->path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
        const bool shown =
            folder || m_extensions.empty() ||
            std::find(m_extensions.begin(), m_extensions.end(), ext) != m_extensions.end();
        if (shown) m_entries.emplace_back(name, folder);
    }
    std::sort(m_entries.begin(), m_entries.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second : a.first < b.first;
    });
}

void FileDialog::draw() {
    if (!m_open) return;
    if (m_justOpened) ImGui::OpenPopup(m_title.c_str()), m_justOpened = false;
    ImGui::SetNextWindowSize(ImVec2(620, 460), ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal(m_title.c_str(), &m_open)) return;
    ImGui::TextWrapped("%s", m_folder.c_str());
    if (ImGui::Button("Up")) {
        m_folder = fs::path(m_folder).parent_path().string();
        list();
    }
    ImGui::BeginChild("entries", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() * 2), true);
    std::string enter, pick;
    for (const auto& [name, folder] : m_entries) {
        const std::string label = folder ? name + "/" : name;
        if (ImGui::Selectable(label.c_str(), std::strcmp(m_name, name.c_str()) == 0,
                              ImGuiSelectableFlags_AllowDoubleClick)) {
            if (folder) {
                if (ImGui::IsMouseDoubleClicked(0)) enter = name;
            } else {
                std::snprintf(m_name, sizeof m_name, "%s", name.c_str());
                if (ImGui::IsMouseDoubleClicked(0)) pick = name;
            }
        }
    }
    ImGui::EndChild();
    if (!enter.empty()) {
        m_folder = (fs::path(m_folder) / enter).string();
        list();
    }
    ImGui::InputText(m_saving ? "file name" : "file", m_name, sizeof m_name);
    ImGui::SameLine();
    if (ImGui::Button(m_saving ? "Save" : "Open") && m_name[0]) pick = m_name;
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) m_open = false;
    if (!pick.empty()) {
        const fs::path typed(pick);
        const std::string path =
            typed.is_absolute() ? typed.string() : (fs::path(m_folder) / typed).string();
        m_open = false;
        if (m_chosen) m_chosen(path);
    }
    if (!m_open) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

}  // namespace flarekit::studio
