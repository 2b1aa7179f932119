#include "apps/vimg-player/image_view.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vimg::player_app {

namespace {

// Even-odd scanline fill of a polygon given in pixels; every `stripe_px` rows alternate shade.
void fill_polygon(SDL_Renderer* renderer, const std::vector<SDL_FPoint>& points, double stripe_px, Uint8 shade) {
  if (points.size() < 3) return;
  float top = points[0].y, bottom = points[0].y;
  for (const auto& p : points) {
    top = std::min(top, p.y);
    bottom = std::max(bottom, p.y);
  }
  std::vector<float> crossings;
  for (int y = static_cast<int>(std::floor(top)); y <= static_cast<int>(std::ceil(bottom)); ++y) {
    const float scan = static_cast<float>(y) + 0.5f;
    crossings.clear();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const SDL_FPoint& a = points[i];
      const SDL_FPoint& b = points[(i + 1) % points.size()];
      if ((a.y <= scan && b.y > scan) || (b.y <= scan && a.y > scan)) {
        crossings.push_back(a.x + (scan - a.y) / (b.y - a.y) * (b.x - a.x));
      }
    }
    std::sort(crossings.begin(), crossings.end());
    const bool dark = stripe_px > 1.0 && std::fmod(static_cast<double>(y) / stripe_px, 2.0) >= 1.0;
    const auto level = static_cast<Uint8>(dark ? shade * 3 / 4 : shade);
    SDL_SetRenderDrawColor(renderer, level, level, static_cast<Uint8>(std::min(255, level + 20)), 255);
    for (std::size_t i = 0; i + 1 < crossings.size(); i += 2) {
      SDL_RenderDrawLineF(renderer, crossings[i], static_cast<float>(y), crossings[i + 1], static_cast<float>(y));
    }
  }
}

std::vector<SDL_FPoint> ellipse_points(const ViewTransform& view, double cx, double cy, double rx, double ry) {
  std::vector<SDL_FPoint> points;
  constexpr int kSegments = 72;
  for (int i = 0; i < kSegments; ++i) {
    const double angle = 2.0 * M_PI * i / kSegments;
    points.push_back({static_cast<float>(view.to_x_px(cx + rx * std::cos(angle))),
                      static_cast<float>(view.to_y_px(cy + ry * std::sin(angle)))});
  }
  return points;
}

Uint8 shade_for(double gain) { return static_cast<Uint8>(90 + std::clamp(gain, 0.0, 1.0) * 120); }

void draw_element(SDL_Renderer* renderer, const Element& element, const ViewTransform& view) {
  if (const auto* group = std::get_if<Group>(&element.body)) {
    for (const auto& child : group->children) draw_element(renderer, child, view);
  } else if (const auto* surface = std::get_if<Surface>(&element.body)) {
    std::vector<SDL_FPoint> points;
    if (surface->shape == SurfaceShape::rect) {
      const double x0 = surface->x_mm, y0 = surface->y_mm, x1 = x0 + surface->width_mm, y1 = y0 + surface->height_mm;
      for (const auto& [x, y] : {std::pair{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}) {
        points.push_back({static_cast<float>(view.to_x_px(x)), static_cast<float>(view.to_y_px(y))});
      }
    } else if (surface->shape == SurfaceShape::ellipse) {
      points = ellipse_points(view, surface->cx_mm, surface->cy_mm, surface->rx_mm, surface->ry_mm);
    } else {
      for (const auto& p : surface->points) {
        points.push_back({static_cast<float>(view.to_x_px(p.x_mm)), static_cast<float>(view.to_y_px(p.y_mm))});
      }
    }
    fill_polygon(renderer, points, surface->period_mm * view.px_per_mm / 2.0, shade_for(surface->gain));
  } else if (const auto* line = std::get_if<Line>(&element.body)) {
    const double dx = line->x2_mm - line->x1_mm, dy = line->y2_mm - line->y1_mm;
    const double length = std::hypot(dx, dy);
    if (length <= 0.0) return;
    const double nx = -dy / length * line->width_mm / 2.0, ny = dx / length * line->width_mm / 2.0;
    std::vector<SDL_FPoint> band;
    for (const auto& [x, y] : {std::pair{line->x1_mm + nx, line->y1_mm + ny}, {line->x2_mm + nx, line->y2_mm + ny},
                               {line->x2_mm - nx, line->y2_mm - ny}, {line->x1_mm - nx, line->y1_mm - ny}}) {
      band.push_back({static_cast<float>(view.to_x_px(x)), static_cast<float>(view.to_y_px(y))});
    }
    fill_polygon(renderer, band, 0.0, static_cast<Uint8>(shade_for(line->gain) / 2));
  } else if (const auto* dot = std::get_if<Dot>(&element.body)) {
    fill_polygon(renderer, ellipse_points(view, dot->x_mm, dot->y_mm, dot->radius_mm, dot->radius_mm), 0.0,
                 static_cast<Uint8>(shade_for(dot->gain) / 3));
  }
}

}  // namespace

void draw_image(SDL_Renderer* renderer, const Image& image, const ViewTransform& view) {
  const SDL_FRect canvas{static_cast<float>(view.to_x_px(0.0)), static_cast<float>(view.to_y_px(0.0)),
                         static_cast<float>(image.width_mm * view.px_per_mm),
                         static_cast<float>(image.height_mm * view.px_per_mm)};
  SDL_SetRenderDrawColor(renderer, 250, 250, 245, 255);
  SDL_RenderFillRectF(renderer, &canvas);
  for (const auto& element : image.children) draw_element(renderer, element, view);
  SDL_SetRenderDrawColor(renderer, 120, 120, 120, 255);
  SDL_RenderDrawRectF(renderer, &canvas);
}

}  // namespace vimg::player_app
