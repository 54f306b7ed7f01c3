#pragma once
// A small file chooser drawn with ImGui (1.86 has none): a path field, the folder's entries
// filtered by extension, parent/child navigation. Modal; one instance per purpose.
#include <functional>
#include <string>
#include <vector>

namespace corbel::editor {

class FileDialog {
 public:
  enum class Mode { Open, Save };
  // `extensions` like {".corbel"}; the first is appended on save when the name has none
  // of them.
  void open(Mode mode, std::string title, std::vector<std::string> extensions, std::string startPath,
            std::function<void(const std::string&)> onChoose);
  // Call every frame; draws the modal while it is open.
  void draw();
  bool isOpen() const { return visible_; }

 private:
  void refresh();
  Mode mode_ = Mode::Open;
  std::string title_;
  std::vector<std::string> extensions_;
  std::string folder_;
  char name_[512] = {};
  std::vector<std::pair<std::string, bool>> entries_;  // name, is folder
  std::function<void(const std::string&)> onChoose_;
  bool visible_ = false;
  bool justOpened_ = false;
  std::string error_;
};

}  // namespace corbel::editor
