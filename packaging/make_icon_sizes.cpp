// Writes the application icon at the sizes desktop menus and file managers use, from the
// window icon, for the install: make_icon_sizes SOURCE.png OUT_DIR SIZE... writes
// OUT_DIR/SIZE/isurface.png. Sizes above the source's are refused: an icon is scaled down,
// never blurred up.
#include <stb/stb_image.h>
#include <stb/stb_image_resize.h>
#include <stb/stb_image_write.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: make_icon_sizes SOURCE.png OUT_DIR SIZE...\n");
    return 2;
  }
  int width = 0, height = 0, channels = 0;
  unsigned char* source = stbi_load(argv[1], &width, &height, &channels, 4);
  if (!source) {
    std::fprintf(stderr, "make_icon_sizes: cannot read %s\n", argv[1]);
    return 1;
  }
  int status = 0;
  for (int k = 3; k < argc && status == 0; ++k) {
    const int size = std::atoi(argv[k]);
    if (size <= 0 || size > width || size > height) {
      std::fprintf(stderr, "make_icon_sizes: %s is not a size from 1 to %d\n", argv[k], width);
      status = 1;
      break;
    }
    std::vector<unsigned char> pixels(static_cast<std::size_t>(size) * size * 4);
    stbir_resize_uint8_srgb(source, width, height, 0, pixels.data(), size, size, 0, 4, 3, 0);
    const std::filesystem::path folder = std::filesystem::path(argv[2]) / std::to_string(size);
    std::filesystem::create_directories(folder);
    const std::string out = (folder / "isurface.png").string();
    if (!stbi_write_png(out.c_str(), size, size, 4, pixels.data(), size * 4)) {
      std::fprintf(stderr, "make_icon_sizes: cannot write %s\n", out.c_str());
      status = 1;
    }
  }
  stbi_image_free(source);
  return status;
}
