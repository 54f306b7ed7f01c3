#include "editor/file_dialog.h"

#include <imgui.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

namespace corbel::editor {

namespace fs = std::filesystem;

void FileDialog::open(Mode mode, std::string title, std::vector<std::string> extensions, std::string startPath,
                      std::function<void(const std::string&)> onChoose) {
  mode_ = mode;
  title_ = std::move(title);
  extensions_ = std::move(extensions);
  onChoose_ = std::move(onChoose);
  std::error_code ec;
  fs::path p = startPath.empty() ? fs::current_path(ec) : fs::absolute(startPath, ec);
  if (fs::is_directory(p, ec)) {
    folder_ = p.string();
    name_[0] = '\0';
  } else {
    folder_ = p.parent_path().string();
    std::snprintf(name_, sizeof name_, "%s", p.filename().string().c_str());
  }
  error_.clear();
  refresh();
  visible_ = true;
  justOpened_ = true;
}

void FileDialog::refresh() {
  entries_.clear();
  std::error_code ec;
  for (fs::directory_iterator it(folder_, fs::directory_options::skip_permission_denied, ec), end; !ec && it != end;
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    const bool dir = it->is_directory(ec);
    const std::string ext = it->path().extension().string();
    if (dir || extensions_.empty() || std::find(extensions_.begin(), extensions_.end(), ext) != extensions_.end())
      entries_.emplace_back(name, dir);
  }
  std::sort(entries_.begin(), entries_.end(), [](const auto& a, const auto& b) {
    return a.second != b.second ? a.second > b.second : a.first < b.first;
  });
}

void FileDialog::draw() {
  if (!visible_) return;
  if (justOpened_) {
    ImGui::OpenPopup(title_.c_str());
    justOpened_ = false;
  }
  ImGui::SetNextWindowSize(ImVec2(560, 420), ImGuiCond_Appearing);
  bool keepOpen = true;
  if (ImGui::BeginPopupModal(title_.c_str(), &keepOpen)) {
    ImGui::TextUnformatted(folder_.c_str());
    if (ImGui::Button("Up")) {
      folder_ = fs::path(folder_).parent_path().string();
      refresh();
    }
    bool picked = false;
    ImGui::BeginChild("entries", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() * 2.5f), true);
    for (const auto& [name, dir] : entries_) {
      const std::string label = dir ? name + "/" : name;
      if (ImGui::Selectable(label.c_str(), !dir && name == name_, ImGuiSelectableFlags_AllowDoubleClick)) {
        if (dir) {
          folder_ = (fs::path(folder_) / name).string();
          refresh();
          break;
        }
        std::snprintf(name_, sizeof name_, "%s", name.c_str());
        if (ImGui::IsMouseDoubleClicked(0)) picked = true;
      }
    }
    ImGui::EndChild();
    ImGui::SetNextItemWidth(-120);
    const bool enter = ImGui::InputText("##name", name_, sizeof name_, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    const bool choose = ImGui::Button(mode_ == Mode::Open ? "Open" : "Save") || enter || picked;
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) keepOpen = false;
    if (choose) {
      error_.clear();
      std::string name = name_;
      if (name.empty()) {
        error_ = "Type or pick a file name.";
        keepOpen = true;
      } else {
        fs::path p = fs::path(name).is_absolute() ? fs::path(name) : fs::path(folder_) / name;
        if (mode_ == Mode::Save && !extensions_.empty() &&
            std::find(extensions_.begin(), extensions_.end(), p.extension().string()) == extensions_.end())
          p += extensions_.front();
        std::error_code ec;
        if (mode_ == Mode::Open && !fs::is_regular_file(p, ec)) {
          error_ = "No such file: " + p.string();
          keepOpen = true;
        } else {
          visible_ = false;
          ImGui::CloseCurrentPopup();
          ImGui::EndPopup();
          if (onChoose_) onChoose_(p.string());
          return;
        }
      }
    }
    if (!error_.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", error_.c_str());
    if (!keepOpen) {
      visible_ = false;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  } else {
    visible_ = false;
  }
}

}  // namespace corbel::editor
