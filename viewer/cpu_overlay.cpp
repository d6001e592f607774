// volgraph's renderer of Dear ImGui's draw lists on the CPU (overlay.h CpuOverlay): the
// WebGPU window's overlay, drawn into the frame's bytes before they reach the surface.
#include <algorithm>
#include <array>
#include <cmath>

#include <imgui.h>
#include <imgui_impl_glfw.h>

#include "viewer/overlay.h"

namespace volgraph::viewer {
namespace {

struct Point {
  float x, y;
};

// Twice the signed area of (a, b, p): which side of a → b the point p is on.
float edge(Point a, Point b, Point p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

// The fill rule for a pixel centre exactly on an edge: of two triangles sharing the edge
// (seen in opposite directions), exactly one takes it, so no pixel is blended twice.
bool owns_edge(Point a, Point b) { return b.y > a.y || (b.y == a.y && b.x < a.x); }

std::array<float, 4> unpack(ImU32 c) {  // IM_COL32: R in the low byte, A in the high
  return {float(c & 0xff), float((c >> 8) & 0xff), float((c >> 16) & 0xff), float(c >> 24) / 255.0f};
}

struct Target {
  uint8_t* rgba;
  int width, height;
};

struct Atlas {
  const uint8_t* alpha;
  int width, height;
  float at(float u, float v) const {
    const int x = std::clamp(int(u * float(width)), 0, width - 1), y = std::clamp(int(v * float(height)), 0, height - 1);
    return float(alpha[size_t(y) * size_t(width) + size_t(x)]) / 255.0f;
  }
};

// One triangle, clipped to `clip` (x0, y0, x1, y1 in pixels), blended over the target.
void fill(const Target& t, const Atlas& atlas, const ImDrawVert* v[3], const ImVec4& clip) {
  Point p[3] = {{v[0]->pos.x, v[0]->pos.y}, {v[1]->pos.x, v[1]->pos.y}, {v[2]->pos.x, v[2]->pos.y}};
  float area = edge(p[0], p[1], p[2]);
  if (area == 0) return;
  if (area < 0) {  // one orientation for every triangle: shared edges are seen both ways
    std::swap(p[1], p[2]);
    std::swap(v[1], v[2]);
    area = -area;
  }
  const int x0 = std::max({int(std::floor(std::min({p[0].x, p[1].x, p[2].x}))), int(clip.x), 0});
  const int y0 = std::max({int(std::floor(std::min({p[0].y, p[1].y, p[2].y}))), int(clip.y), 0});
  const int x1 = std::min({int(std::ceil(std::max({p[0].x, p[1].x, p[2].x}))), int(std::ceil(clip.z)), t.width});
  const int y1 = std::min({int(std::ceil(std::max({p[0].y, p[1].y, p[2].y}))), int(std::ceil(clip.w)), t.height});
  const std::array<float, 4> c[3] = {unpack(v[0]->col), unpack(v[1]->col), unpack(v[2]->col)};
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const Point centre{float(x) + 0.5f, float(y) + 0.5f};
      const float w[3] = {edge(p[1], p[2], centre), edge(p[2], p[0], centre), edge(p[0], p[1], centre)};
      const bool inside = (w[0] > 0 || (w[0] == 0 && owns_edge(p[1], p[2]))) && (w[1] > 0 || (w[1] == 0 && owns_edge(p[2], p[0]))) &&
                          (w[2] > 0 || (w[2] == 0 && owns_edge(p[0], p[1])));
      if (!inside) continue;
      const float b[3] = {w[0] / area, w[1] / area, w[2] / area};
      const float u = b[0] * v[0]->uv.x + b[1] * v[1]->uv.x + b[2] * v[2]->uv.x;
      const float s = b[0] * v[0]->uv.y + b[1] * v[1]->uv.y + b[2] * v[2]->uv.y;
      const float alpha = (b[0] * c[0][3] + b[1] * c[1][3] + b[2] * c[2][3]) * atlas.at(u, s);
      uint8_t* pixel = t.rgba + (size_t(y) * size_t(t.width) + size_t(x)) * 4;
      for (int k = 0; k < 3; ++k) {
        const float source = b[0] * c[0][k] + b[1] * c[1][k] + b[2] * c[2][k];
        pixel[k] = uint8_t(std::clamp(std::lround(source * alpha + float(pixel[k]) * (1 - alpha)), 0L, 255L));
      }
    }
  }
}

}  // namespace

CpuOverlay::CpuOverlay(GLFWwindow* window) : Overlay(window, false) {
  ImGuiIO& io = ImGui::GetIO();
  io.BackendRendererName = "volgraph_cpu";
  unsigned char* pixels = nullptr;
  io.Fonts->GetTexDataAsAlpha8(&pixels, &atlas_width_, &atlas_height_);
  atlas_.assign(pixels, pixels + size_t(atlas_width_) * size_t(atlas_height_));
  io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(intptr_t(1)));  // the one texture: the atlas
}

CpuOverlay::~CpuOverlay() { ImGui::GetIO().BackendRendererName = nullptr; }

void CpuOverlay::draw(std::vector<uint8_t>& rgba8, Extent size) const {
  const ImDrawData* data = ImGui::GetDrawData();
  if (!data || rgba8.size() < size_t(size.width) * size.height * 4) return;
  const Target target{rgba8.data(), int(size.width), int(size.height)};
  const Atlas atlas{atlas_.data(), atlas_width_, atlas_height_};
  const ImVec2 origin = data->DisplayPos, scale = data->FramebufferScale;
  for (int n = 0; n < data->CmdListsCount; ++n) {
    const ImDrawList* list = data->CmdLists[n];
    for (const ImDrawCmd& cmd : list->CmdBuffer) {
      if (cmd.UserCallback) continue;  // the viewer's panel declares none
      const ImVec4 clip{(cmd.ClipRect.x - origin.x) * scale.x, (cmd.ClipRect.y - origin.y) * scale.y, (cmd.ClipRect.z - origin.x) * scale.x,
                        (cmd.ClipRect.w - origin.y) * scale.y};
      for (unsigned int i = 0; i + 2 < cmd.ElemCount; i += 3) {
        const ImDrawVert* v[3];
        for (int k = 0; k < 3; ++k) v[k] = &list->VtxBuffer[int(cmd.VtxOffset + list->IdxBuffer[int(cmd.IdxOffset + i + unsigned(k))])];
        fill(target, atlas, v, clip);
      }
    }
  }
}

}  // namespace volgraph::viewer
