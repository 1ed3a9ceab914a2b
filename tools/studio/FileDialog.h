// SPDX-License-Identifier: Apache-2.0
// A file chooser drawn with Dear ImGui (the library has none): a folder's entries, folders
// first, filtered by extension, and a name field for saving. Paths typed in are taken as they
// are, relative to the working folder as on the command line.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace flarekit::studio {

class FileDialog {
  public:
    //! Opens the chooser titled `title` showing files ending in one of `extensions` (all when
    //! empty); `chosen` gets the path when the user confirms.
    void open(const std::string& title, std::vector<std::string> extensions, bool saving,
              std::function<void(const std::string&)> chosen);
    //! Draws it while open (call every frame).
    void draw();
    bool isOpen() const { return m_open; }

  private:
    void list();
    bool m_open = false, m_saving = false, m_justOpened = false;
    std::string m_title, m_folder;
    char m_name[1024] = {};
    std::vector<std::string> m_extensions;
    std::vector<std::pair<std::string, bool>> m_entries;  //!< name, is a folder
    std::function<void(const std::string&)> m_chosen;
};

}  // namespace flarekit::studio
