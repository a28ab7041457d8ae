// A picture uploaded to a GL texture with its mipmaps and, where the driver has the extension,
// anisotropic filtering: a print on a fine fold or a photo shown small averages its texels
// instead of aliasing into moiré. Shared by the cloth's prints and the fold plot's photo.
#pragma once

namespace foldlab::gui {

// `rgba` is width x height pixels, 8 bits a channel, top row first. `repeat`: tiled (a print);
// otherwise clamped at the edges (a photo).
void upload_mipmapped(unsigned texture, int width, int height, const void* rgba, bool repeat);

}  // namespace foldlab::gui
