// Which pixel of the image a band's pixel is: the band covers the pixels
// of the frame's window from `firstPixel` on, counted along the window's
// rows, so that a crop of any shape renders in as few bands as its size
// allows. Random numbers are keyed by the image's pixel, so the band a
// pixel falls in never changes its picture. Needs `frame`.
#ifndef FACET_RAYCAST_BAND_PIXELS_GLSL
#define FACET_RAYCAST_BAND_PIXELS_GLSL

uint image_pixel(uint band_pixel) {
  uint in_window = frame.firstPixel + band_pixel;
  return (frame.windowY + in_window / frame.windowWidth) * uint(frame.width) + frame.windowX +
         in_window % frame.windowWidth;
}

#endif
