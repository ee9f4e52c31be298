#include "screen_image.h"

#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <stdexcept>

namespace ellipse_collision {
namespace test {
namespace {

/// Position of the lowest set bit of a channel mask, and the channel's width in bits.
void maskShape(unsigned long mask, int& shift, int& bits) {
  shift = 0;
  bits = 0;
  if (mask == 0) return;
  while (!(mask & 1UL)) {
    mask >>= 1;
    ++shift;
  }
  while (mask & 1UL) {
    mask >>= 1;
    ++bits;
  }
}

std::uint8_t channel(unsigned long pixel, unsigned long mask) {
  int shift = 0;
  int bits = 0;
  maskShape(mask, shift, bits);
  if (bits == 0) return 0;
  const unsigned long value = (pixel & mask) >> shift;
  const unsigned long max = (1UL << bits) - 1;
  return static_cast<std::uint8_t>(value * 255 / max);
}

}  // namespace

ScreenImage ScreenImage::grab() {
  std::unique_ptr<Display, int (*)(Display*)> display(XOpenDisplay(nullptr), XCloseDisplay);
  if (!display) throw std::runtime_error("cannot open the X display $DISPLAY");
  const Window root = DefaultRootWindow(display.get());
  XWindowAttributes attributes;
  if (!XGetWindowAttributes(display.get(), root, &attributes)) {
    throw std::runtime_error("cannot read the root window's size");
  }
  // XDestroyImage is a macro, hence the lambda.
  const auto destroy = [](XImage* image) { XDestroyImage(image); };
  std::unique_ptr<XImage, decltype(destroy)> image(
      XGetImage(display.get(), root, 0, 0, attributes.width, attributes.height, AllPlanes, ZPixmap),
      destroy);
  if (!image) throw std::runtime_error("XGetImage failed on the root window");

  ScreenImage result;
  result.width_ = attributes.width;
  result.height_ = attributes.height;
  result.pixels_.resize(static_cast<std::size_t>(result.width_) * result.height_);
  for (int y = 0; y < result.height_; ++y) {
    for (int x = 0; x < result.width_; ++x) {
      const unsigned long pixel = XGetPixel(image.get(), x, y);
      result.set(x, y,
                 {channel(pixel, image->red_mask), channel(pixel, image->green_mask),
                  channel(pixel, image->blue_mask)});
    }
  }
  return result;
}

void ScreenImage::savePpm(const std::string& path) const {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write '" + path + "'");
  out << "P6\n" << width_ << " " << height_ << "\n255\n";
  for (const Rgb& pixel : pixels_) out.write(reinterpret_cast<const char*>(pixel.data()), 3);
}

PanelRect ScreenImage::findArea(const Rgb& colour, int min_count) const {
  // Anti-aliased text elsewhere may hit the colour in a few pixels; an area has many per line.
  std::vector<int> per_row(height_, 0);
  std::vector<int> per_column(width_, 0);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      if (at(x, y) != colour) continue;
      ++per_row[y];
      ++per_column[x];
    }
  }
  PanelRect box{width_, height_, -1, -1};
  for (int y = 0; y < height_; ++y) {
    if (per_row[y] < min_count) continue;
    box.top = std::min(box.top, y);
    box.bottom = std::max(box.bottom, y);
  }
  for (int x = 0; x < width_; ++x) {
    if (per_column[x] < min_count) continue;
    box.left = std::min(box.left, x);
    box.right = std::max(box.right, x);
  }
  return box;
}

}  // namespace test
}  // namespace ellipse_collision
