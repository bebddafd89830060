#pragma once
/// \file render.hpp
/// Headless pictures of a mesh, for papers, reports and eyeballing: a z-buffered software rasterizer
/// with smooth (per-pixel interpolated, area-weighted vertex normal) Blinn-Phong shading, a wireframe
/// overlay, per-vertex scalar fields on a diverging or sequential colour map with a legend, and
/// isophote (zebra) stripes that expose normal discontinuities. Single-threaded and deterministic:
/// the same mesh and options always give the same pixels.
///
/// Camera: looks at the centre of the mesh's bounding sphere from the direction
/// (cos e cos a, cos e sin a, sin e) for azimuth a and elevation e (degrees; z is up) and frames the
/// whole sphere. Camera coordinates: x to the right, y up, z towards the viewer.

#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace isopatch {

/// An 8-bit RGB colour.
struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

/// A linear RGB colour with channels in [0, 1].
using Colour = Vec3;

/// A picture of width x height RGB pixels, row 0 at the top.
class Image {
 public:
  Image() = default;
  /// \throw InputError unless width >= 1 and height >= 1.
  Image(int width, int height, Rgb fill = Rgb{255, 255, 255});

  int width() const { return width_; }
  int height() const { return height_; }
  /// \pre 0 <= x < width(), 0 <= y < height()
  Rgb at(int x, int y) const;
  /// Sets one pixel. Pixels outside the picture are ignored, so drawing primitives may overhang.
  void set(int x, int y, Rgb colour);
  /// The pixels as rows of R, G, B bytes, top row first.
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> bytes_;
};

/// Largest accepted width or height of a rendered picture.
inline constexpr int kMaxImageSide = 8192;

enum class RenderMode {
  Shaded,       ///< lit surface
  Wireframe,    ///< lit surface with its edges drawn on top
  ScalarField,  ///< signed per-vertex values on blue-white-red over [-m, m], with a legend
  Isophotes,    ///< alternating light and dark stripes of equal angle between normal and light
  Error,        ///< |per-vertex values| on a sequential light-yellow to dark-red map over [0, m]
};

enum class CameraKind { Perspective, Orthographic };

/// Blinn-Phong light fixed to the camera. For a unit normal n (flipped towards the viewer on back
/// faces), l = normalize(direction) and h = normalize(l + (0, 0, 1)), a surface of colour c shows
///   c * (ambient + diffuse * max(0, n.l)) + specular * max(0, n.h)^shininess     (Shaded, Wireframe)
///   c * (field_ambient + (1 - field_ambient) * max(0, n.l))                     (field modes)
/// per channel, clamped to [0, 1] and rounded to 8 bits. The field modes are lit softly, so that the
/// colours stay readable against the legend. Isophotes: the Shaded colour on even stripes, a fifth
/// of it on odd ones.
struct Lighting {
  Vec3 direction = Vec3(-0.35, 0.45, 1.0);  ///< towards the light, camera coordinates
  double ambient = 0.25;
  double diffuse = 0.75;
  double specular = 0.25;
  double shininess = 40.0;
  double field_ambient = 0.6;
};

struct RenderOptions {
  int width = 800;  ///< pixels, 1..kMaxImageSide
  int height = 800;
  RenderMode mode = RenderMode::Shaded;
  double azimuth = 30.0;    ///< degrees
  double elevation = 25.0;  ///< degrees
  CameraKind camera = CameraKind::Perspective;
  double field_of_view = 30.0;  ///< degrees, in (0, 170); perspective only
  Lighting lighting;
  Colour surface_colour = Colour(0.72, 0.78, 0.88);  ///< front faces in Shaded, Wireframe, Isophotes
  Colour back_colour = Colour(0.92, 0.70, 0.50);     ///< back faces (inside of open or flipped parts)
  Colour background = Colour(0.95, 0.95, 0.95);
  Colour edge_colour = Colour(0.10, 0.10, 0.14);
  /// Values of the field modes: `values` when not empty (one per vertex), else the attribute `field`.
  std::string field;
  std::vector<double> values;
  /// Half-width m of the colour map's range; by default the `percentile`-th percentile of |value|
  /// over the finite values (robust against a few outliers). Values beyond the range saturate.
  std::optional<double> range;
  double percentile = 98.0;
  Colour missing_colour = Colour(0.55, 0.55, 0.55);  ///< where a value is NaN or infinite
  int isophote_stripes = 12;  ///< stripes over the angle range [0, 180] degrees between n and l
  bool legend = true;         ///< colour bar with the range, field modes only
  std::string caption;        ///< optional text at the top left (A-Z, 0-9 and a little punctuation)
  /// Samples per pixel along each axis (antialiasing), 1..4; lowered for huge pictures so that at
  /// most 2^26 samples are used.
  int supersampling = 2;
};

/// What a render decided, for summaries.
struct RenderInfo {
  double range = 0.0;              ///< the colour map's m (field modes), else 0
  std::size_t missing_values = 0;  ///< vertices whose value is NaN or infinite
};

/// Draws `mesh` as `options` say. Fills `info` when given.
/// \throw InputError for a mesh without triangles or failing Mesh::validate(), a size outside
///        1..kMaxImageSide, non-finite view angles, a bad field of view, stripes < 1, supersampling
///        outside 1..4, a range that is not finite and positive, a percentile outside (0, 100], or
///        (field modes) missing values: no `values` and no attribute named `field`, or a count that
///        is not the vertex count.
Image render_mesh(const Mesh& mesh, const RenderOptions& options, RenderInfo* info = nullptr);

/// The colours the field modes (ScalarField, Error) of render_mesh give the vertices, before lighting:
/// the same values, range and colour maps (missing_colour where a value is NaN or infinite), turned
/// from the renderer's display (sRGB-encoded) values into linear RGB in [0, 1], as glTF's COLOR_0
/// wants them (write_mesh in mesh_io.hpp). Fills `info` (range, missing values) when given.
/// \throw InputError as render_mesh for the options and values, and for a mode that is not a field mode.
std::vector<Colour> field_vertex_colours(const Mesh& mesh, const RenderOptions& options,
                                         RenderInfo* info = nullptr);

/// Writes `image` as an 8-bit RGB PNG. \throw IoError when the file cannot be written,
/// InputError for an empty image.
void write_png(const Image& image, const std::string& path);

}  // namespace isopatch
