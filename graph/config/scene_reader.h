// Reads the "scene" section of one config file onto the scene gathered so far.
#pragma once

#include "graph/config/json_reader.h"
#include "graph/scene/scene.h"

namespace volgraph::config {

// Camera, background and media replace what includes gave; materials replace by
// name; objects, lights and volumes add to the list.
void read_scene(const Node& node, Scene& scene);

}  // namespace volgraph::config
