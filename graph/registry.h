// Pass types by name. Built explicitly (no static registration): see passes/passes.h.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "graph/pass_decl.h"

namespace volgraph {

class PassRegistry {
 public:
  // Adds a pass type; a second type of the same name is a programming error (throws).
  const PassDecl& add(PassDecl decl);
  const PassDecl* find(std::string_view name) const;
  std::vector<std::string> names() const;  // in registration order
  const std::vector<std::unique_ptr<PassDecl>>& all() const { return decls_; }

  // Fills in what the scene's files hold that graph/ does not read (which glTF objects
  // have translucent materials: Object::translucent_in_file), once after a config's scene
  // is read and before its graph is wired; passes/ installs it. A file it cannot read it
  // leaves alone (the passes that load it report the problem).
  using SceneAnnotator = std::function<void(Scene&)>;
  void set_scene_annotator(SceneAnnotator annotator) { annotator_ = std::move(annotator); }
  void annotate(Scene& scene) const {
    if (annotator_) annotator_(scene);
  }

 private:
  std::vector<std::unique_ptr<PassDecl>> decls_;
  SceneAnnotator annotator_;
};

}  // namespace volgraph
