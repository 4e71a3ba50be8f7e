#pragma once
/// \file ros_map.hpp
/// ROS map_server maps: a YAML metadata file (a strict subset of YAML: the keys map_server reads)
/// naming a PGM image (P2 plain or P5 binary, maxval 1..65535), converted to pathref's binary
/// grid with map_server's occupancy rule (p = (maxval - v) / maxval, or v / maxval when negated;
/// occupied if p > occupied_thresh, free if p < free_thresh, otherwise unknown) and an explicit
/// policy for unknown cells (blocked by default).
/// Spec: spec/formats.md#ros-map-yaml, spec/formats.md#pgm, spec/formats.md#ros-occupancy
/// (grammar, every error message, limits, the reading of trinary/scale/raw for a binary grid).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "pathref/grid/grid.hpp"
#include "pathref/io/grid_text.hpp"

namespace pathref::io {

// ---- PGM ------------------------------------------------------------------------------------

/// A grayscale image as read from a PGM file: row 0 is the TOP row, as in the file.
struct PgmImage {
  std::int64_t width = 0;
  std::int64_t height = 0;
  std::uint32_t maxval = 255;          ///< 1..65535
  std::vector<std::uint16_t> pixels;   ///< width*height samples, row-major, top row first
  // Where the maxval was written (for errors that concern the image as a whole).
  std::size_t maxval_line = 0;
  std::size_t maxval_column = 0;

  /// Same size, maxval and samples (positions are not compared).
  friend bool operator==(const PgmImage& a, const PgmImage& b) {
    return a.width == b.width && a.height == b.height && a.maxval == b.maxval && a.pixels == b.pixels;
  }
};

/// Parses a PGM image, plain (P2) or binary (P5; 2 bytes big-endian per sample when
/// maxval > 255). `filename` is used only in error messages. Throws ParseError(filename, line,
/// column, message) for any deviation from spec/formats.md#pgm; for P5 pixel data the position
/// is where the pixel data starts and the message gives the byte offset. W*H <= Grid::max_cells
/// and the size of the pixel data are checked before anything is allocated, so the memory used
/// is bounded by about twice the size of `bytes`.
[[nodiscard]] PgmImage parse_pgm(std::string_view bytes, std::string_view filename);

/// Binary PGM (P5): "P5\nW H\nMAXVAL\n" then the samples (1 byte each, or 2 big-endian bytes
/// when maxval > 255). Pre (DomainError): width, height >= 1, maxval in [1, 65535],
/// pixels.size() == width*height, every sample <= maxval. parse_pgm(to_pgm_p5(i)) == i.
[[nodiscard]] std::string to_pgm_p5(const PgmImage& image);

/// Plain PGM (P2): "P2\nW H\nMAXVAL\n" then one text line per image row, samples separated by
/// one space. Same preconditions and guarantee as to_pgm_p5.
[[nodiscard]] std::string to_pgm_p2(const PgmImage& image);

// ---- map_server YAML ------------------------------------------------------------------------

/// map_server's `mode` key. Spec: spec/formats.md#ros-occupancy.
enum class RosMapMode { trinary, scale, raw };

/// What a cell that is neither free nor occupied becomes in pathref's binary grid.
/// Spec: spec/formats.md#ros-occupancy (default: blocked, the conservative choice).
enum class UnknownAs { blocked, free };

/// "trinary" | "scale" | "raw"; "blocked" | "free" (UsageError on anything else).
[[nodiscard]] RosMapMode parse_ros_map_mode(std::string_view name);
[[nodiscard]] std::string_view to_string(RosMapMode mode) noexcept;
[[nodiscard]] UnknownAs parse_unknown_as(std::string_view name);
[[nodiscard]] std::string_view to_string(UnknownAs u) noexcept;

/// The contents of a map_server YAML file.
struct RosMapMeta {
  std::string image;                       ///< as written (relative to the YAML file, or absolute)
  double resolution = 0.0;                 ///< metres per cell, finite and > 0
  std::array<double, 3> origin{};          ///< x, y (metres) of the lower-left cell's corner, yaw (rad)
  bool negate = false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  RosMapMode mode = RosMapMode::trinary;   ///< `mode` is optional; trinary when absent
  // Where the image value was written (errors about the image file point here).
  std::size_t image_line = 0;
  std::size_t image_column = 0;

  /// Same values (positions are not compared).
  friend bool operator==(const RosMapMeta& a, const RosMapMeta& b) {
    return a.image == b.image && a.resolution == b.resolution && a.origin == b.origin &&
           a.negate == b.negate && a.occupied_thresh == b.occupied_thresh &&
           a.free_thresh == b.free_thresh && a.mode == b.mode;
  }
};

/// Reader options. Spec: spec/formats.md#ros-occupancy, spec/formats.md#ros-map-yaml.
struct RosMapOptions {
  UnknownAs unknown = UnknownAs::blocked;  ///< what unknown (and scale's in-between) cells become
  bool allow_unknown_keys = false;         ///< ignore keys map_server does not read (else an error)
};

/// Parses map_server YAML metadata (the subset of spec/formats.md#ros-map-yaml). Throws
/// ParseError(filename, line, column, message) on any deviation, on a missing required key and
/// on an unknown key unless `allow_unknown_keys`.
[[nodiscard]] RosMapMeta parse_ros_yaml(std::string_view text, std::string_view filename,
                                        bool allow_unknown_keys = false);

/// Writes metadata in the accepted subset: image as a double-quoted string, numbers in the
/// shortest form that reads back exactly, so parse_ros_yaml(to_ros_yaml(m)) == m.
/// Pre (DomainError): the values parse_ros_yaml would accept (non-empty image without control
/// characters, finite resolution > 0, finite origin, 0 <= free_thresh <= occupied_thresh <= 1,
/// not raw with negate).
[[nodiscard]] std::string to_ros_yaml(const RosMapMeta& meta);

// ---- occupancy --------------------------------------------------------------------------------

/// map_server's three-way classification of one pixel.
enum class Occupancy { free, occupied, unknown };

/// Classifies sample v of an image with the given maxval under `meta` (mode, negate,
/// thresholds). trinary and scale: p = (maxval - v) / maxval (v / maxval if negate), binary64;
/// occupied if p > occupied_thresh, else free if p < free_thresh, else unknown. raw (maxval 255,
/// no negate): v > 100 is unknown, otherwise p = v / 100 with the same thresholds.
/// Source: ROS map_server (wiki.ros.org/map_server, "Value Interpretation"); Nav2 map_io.
/// Spec: spec/formats.md#ros-occupancy. Pre: 1 <= maxval <= 65535, v <= maxval; for raw maxval == 255 and
/// !negate (DomainError).
[[nodiscard]] Occupancy classify_pixel(std::uint32_t v, std::uint32_t maxval, const RosMapMeta& meta);

/// A map_server map converted to pathref's grid, with its metric frame.
struct RosMap {
  MapFile map;                      ///< grid (image row 0 = top = y H-1); no start/goal; name ""
  RosMapMeta meta;                  ///< the YAML's values (resolution, origin, thresholds, ...)
  std::string image_path;           ///< the image file actually read (resolved against the YAML)
  std::int64_t unknown_cells = 0;   ///< cells classified unknown (then set per options.unknown)
};

/// Converts an image with the metadata: cell (x, y) comes from image column x, row H-1-y.
/// Throws ParseError(image_name, maxval position) for raw mode with maxval != 255.
[[nodiscard]] RosMap ros_map_from_image(const PgmImage& image, const RosMapMeta& meta,
                                        const RosMapOptions& options, std::string_view image_name);

/// The whole pipeline on in-memory files (no file system): parse_ros_yaml, parse_pgm,
/// ros_map_from_image. `image_path` is stored as given.
[[nodiscard]] RosMap parse_ros_map(std::string_view yaml_text, std::string_view yaml_name,
                                   std::string_view pgm_bytes, std::string_view image_path,
                                   const RosMapOptions& options = {});

/// Loads a map_server map: reads `yaml_path`, resolves `image` against the YAML file's
/// directory (absolute paths are kept), reads and converts the PGM. UsageError when the YAML
/// cannot be read (missing, not a regular file, over max_map_file_bytes); ParseError for
/// malformed contents and for an image file that cannot be read (located at the image value).
[[nodiscard]] RosMap load_ros_map(const std::string& yaml_path, const RosMapOptions& options = {});

/// The files of a map written by pathref: free cells 254, blocked cells 0 (map_saver's values),
/// P5 maxval 255; YAML with mode trinary, negate 0, occupied_thresh 0.65, free_thresh 0.196.
struct RosMapFiles {
  std::string yaml;
  std::string pgm;
};

/// Pre (DomainError): resolution finite > 0, origin finite, image_name non-empty without control
/// characters. Guarantee: parse_ros_map(f.yaml, _, f.pgm, _) gives back `grid`, `resolution` and
/// `origin` exactly (with either unknown policy: the writer never produces unknown cells).
[[nodiscard]] RosMapFiles to_ros_map(const grid::Grid& grid, double resolution,
                                     const std::array<double, 3>& origin,
                                     const std::string& image_name);

/// Writes to_ros_map(...) to `yaml_path` and to `<yaml stem>.pgm` in the same directory.
/// UsageError when a file cannot be written.
void write_ros_map(const std::string& yaml_path, const grid::Grid& grid, double resolution,
                   const std::array<double, 3>& origin);

}  // namespace pathref::io
