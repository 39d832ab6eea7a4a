/*
 * pcl_rspd tools: checked point cloud reading and labelled cloud writing, shared by the tools.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "cloud_io.h"

#include <pcl/PCLPointField.h>
#include <pcl/common/io.h>
#include <pcl/io/lzf.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <limits>
#include <new>
#include <sstream>
#include <utility>

namespace rspd_tools
{
namespace
{
/** \brief Headers longer than this are refused: a real header is a few hundred bytes, and the cap
  * keeps a file of random bytes from being scanned whole for a line end. */
constexpr std::size_t kMaxHeaderBytes = 1u << 20;
/** \brief Upper bounds that keep header arithmetic far from overflow. */
constexpr std::uint64_t kMaxFields = 65536;
constexpr std::uint64_t kMaxCount = 1u << 24;

/** \brief A token from a file, made safe to print: printable ASCII only, short. */
std::string
printable (const std::string& s)
{
  std::string r;
  for (const char c : s)
  {
    if (r.size () >= 32)
    {
      r += "...";
      break;
    }
    r += (c >= 32 && c < 127) ? c : '?';
  }
  return r;
}

std::string
lowercase (std::string s)
{
  for (char& c : s)
    c = static_cast<char> (std::tolower (static_cast<unsigned char> (c)));
  return s;
}

std::string
extensionOf (const std::string& path)
{
  const std::size_t slash = path.find_last_of ('/');
  const std::size_t dot = path.find_last_of ('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  return lowercase (path.substr (dot + 1));
}

/** \brief Split on blanks, tabs and carriage returns, dropping empty tokens (as PCL does). */
std::vector<std::string>
tokenize (const std::string& line)
{
  std::vector<std::string> tokens;
  std::size_t i = 0;
  while (i < line.size ())
  {
    while (i < line.size () && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
      ++i;
    const std::size_t start = i;
    while (i < line.size () && line[i] != ' ' && line[i] != '\t' && line[i] != '\r')
      ++i;
    if (i > start)
      tokens.emplace_back (line, start, i - start);
  }
  return tokens;
}

/** \brief Strict unsigned decimal: digits only, no sign, no overflow. */
bool
parseUnsigned (const std::string& s, std::uint64_t& value)
{
  if (s.empty ())
    return false;
  const char* end = s.data () + s.size ();
  const auto result = std::from_chars (s.data (), end, value);
  return result.ec == std::errc () && result.ptr == end;
}

bool
parseDouble (const std::string& s, double& value)
{
  if (s.empty ())
    return false;
  const char* end = s.data () + s.size ();
  const auto result = std::from_chars (s.data (), end, value);
  return result.ec == std::errc () && result.ptr == end;
}

/** \brief Next line of \a text from \a pos, without the '\n'. \return false at the end of text
  * without a line feed (the line is then incomplete). */
bool
nextLine (const std::string& text, std::size_t& pos, std::string& line)
{
  const std::size_t nl = text.find ('\n', pos);
  if (nl == std::string::npos)
    return false;
  line.assign (text, pos, nl - pos);
  pos = nl + 1;
  return true;
}

/** \brief Read up to \a max_bytes from the start of a file. */
bool
readPrefix (const std::string& path, std::size_t max_bytes, std::string& text, std::string& error)
{
  std::ifstream in (path, std::ios::binary);
  if (!in)
  {
    error = path + ": cannot open the file for reading: " + std::strerror (errno);
    return false;
  }
  text.resize (max_bytes);
  in.read (&text[0], static_cast<std::streamsize> (max_bytes));
  text.resize (static_cast<std::size_t> (in.gcount ()));
  return true;
}

/** \brief Size of a PCLPointField datatype in bytes (0 if unknown). */
std::size_t
datatypeSize (std::uint8_t datatype)
{
  switch (datatype)
  {
    case pcl::PCLPointField::INT8:
    case pcl::PCLPointField::UINT8:
      return 1;
    case pcl::PCLPointField::INT16:
    case pcl::PCLPointField::UINT16:
      return 2;
    case pcl::PCLPointField::INT32:
    case pcl::PCLPointField::UINT32:
    case pcl::PCLPointField::FLOAT32:
      return 4;
    case pcl::PCLPointField::INT64:
    case pcl::PCLPointField::UINT64:
    case pcl::PCLPointField::FLOAT64:
      return 8;
    default:
      return 0;
  }
}

/** \brief One scalar of any PCLPointField datatype, as a double. */
double
readScalar (const std::uint8_t* p, std::uint8_t datatype)
{
  switch (datatype)
  {
    case pcl::PCLPointField::INT8: { std::int8_t v; std::memcpy (&v, p, 1); return v; }
    case pcl::PCLPointField::UINT8: { std::uint8_t v; std::memcpy (&v, p, 1); return v; }
    case pcl::PCLPointField::INT16: { std::int16_t v; std::memcpy (&v, p, 2); return v; }
    case pcl::PCLPointField::UINT16: { std::uint16_t v; std::memcpy (&v, p, 2); return v; }
    case pcl::PCLPointField::INT32: { std::int32_t v; std::memcpy (&v, p, 4); return v; }
    case pcl::PCLPointField::UINT32: { std::uint32_t v; std::memcpy (&v, p, 4); return v; }
    case pcl::PCLPointField::INT64: { std::int64_t v; std::memcpy (&v, p, 8); return static_cast<double> (v); }
    case pcl::PCLPointField::UINT64: { std::uint64_t v; std::memcpy (&v, p, 8); return static_cast<double> (v); }
    case pcl::PCLPointField::FLOAT32: { float v; std::memcpy (&v, p, 4); return v; }
    case pcl::PCLPointField::FLOAT64: { double v; std::memcpy (&v, p, 8); return v; }
    default: return std::numeric_limits<double>::quiet_NaN ();
  }
}

const pcl::PCLPointField*
findField (const pcl::PCLPointCloud2& blob, const std::string& name)
{
  for (const auto& f : blob.fields)
    if (f.name == name)
      return &f;
  return nullptr;
}

// ---------------------------------------------------------------------------------------------
// PCD header check
// ---------------------------------------------------------------------------------------------

/** \brief What the PCD header promises. */
struct PcdHeader
{
  std::vector<std::string> names;
  std::vector<std::uint64_t> sizes;
  std::vector<char> types;
  std::vector<std::uint64_t> counts;
  std::uint64_t width = 0;
  std::uint64_t height = 1;
  std::uint64_t points = 0;
  std::string data;            ///< ascii, binary or binary_compressed
  std::size_t header_len = 0;  ///< bytes up to and including the DATA line's line feed
  std::uint64_t point_size = 0;
  std::uint64_t values_per_point = 0;
};

bool
parsePcdHeader (const std::string& path, const std::string& text, std::uint64_t file_size,
                PcdHeader& h, std::string& error, bool require_xyz = true)
{
  const std::string where = path + ": ";
  bool has_fields = false, has_size = false, has_type = false, has_count = false;
  bool has_width = false, has_height = false, has_points = false, has_data = false;
  bool has_viewpoint = false, has_version = false;
  std::size_t pos = 0;
  std::string line;
  std::size_t line_no = 0;
  while (!has_data)
  {
    if (!nextLine (text, pos, line))
    {
      if (text.size () >= kMaxHeaderBytes && file_size > text.size ())
        error = where + "not a PCD file: no DATA line in the first 1 MiB";
      else
        error = where + "not a PCD file: the header has no DATA line";
      return false;
    }
    ++line_no;
    const std::vector<std::string> tok = tokenize (line);
    if (tok.empty () || tok[0][0] == '#')
      continue;
    const std::string& key = tok[0];
    const std::size_t nargs = tok.size () - 1;
    const auto duplicate = [&] (bool& seen) {
      if (seen)
      {
        error = where + "invalid PCD header: " + key + " appears twice";
        return true;
      }
      seen = true;
      return false;
    };
    const auto bad = [&] (const std::string& what) {
      error = where + "invalid PCD header: " + what + " (line " + std::to_string (line_no) + ")";
      return false;
    };
    if (key == "VERSION")
    {
      if (duplicate (has_version))
        return false;
    }
    else if (key == "FIELDS" || key == "COLUMNS")
    {
      if (duplicate (has_fields))
        return false;
      if (nargs == 0 || nargs > kMaxFields)
        return bad ("FIELDS must list between 1 and 65536 names");
      h.names.assign (tok.begin () + 1, tok.end ());
    }
    else if (key == "SIZE")
    {
      if (duplicate (has_size))
        return false;
      for (std::size_t i = 1; i < tok.size (); ++i)
      {
        std::uint64_t v = 0;
        if (!parseUnsigned (tok[i], v) || (v != 1 && v != 2 && v != 4 && v != 8))
          return bad ("SIZE '" + printable (tok[i]) + "' is not 1, 2, 4 or 8");
        h.sizes.push_back (v);
      }
    }
    else if (key == "TYPE")
    {
      if (duplicate (has_type))
        return false;
      for (std::size_t i = 1; i < tok.size (); ++i)
      {
        if (tok[i].size () != 1 || (tok[i][0] != 'I' && tok[i][0] != 'U' && tok[i][0] != 'F'))
          return bad ("TYPE '" + printable (tok[i]) + "' is not I, U or F");
        h.types.push_back (tok[i][0]);
      }
    }
    else if (key == "COUNT")
    {
      if (duplicate (has_count))
        return false;
      for (std::size_t i = 1; i < tok.size (); ++i)
      {
        std::uint64_t v = 0;
        if (!parseUnsigned (tok[i], v) || v == 0 || v > kMaxCount)
          return bad ("COUNT '" + printable (tok[i]) + "' is not a positive count");
        h.counts.push_back (v);
      }
    }
    else if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS")
    {
      bool& seen = key == "WIDTH" ? has_width : (key == "HEIGHT" ? has_height : has_points);
      if (duplicate (seen))
        return false;
      std::uint64_t v = 0;
      if (nargs != 1 || !parseUnsigned (tok[1], v) || v > std::numeric_limits<std::uint32_t>::max ())
        return bad (key + " needs one unsigned 32-bit number");
      (key == "WIDTH" ? h.width : (key == "HEIGHT" ? h.height : h.points)) = v;
    }
    else if (key == "VIEWPOINT")
    {
      if (duplicate (has_viewpoint))
        return false;
      if (nargs != 7)
        return bad ("VIEWPOINT needs 7 numbers (tx ty tz qw qx qy qz)");
      for (std::size_t i = 1; i < tok.size (); ++i)
      {
        double v = 0.0;
        if (!parseDouble (tok[i], v) || !std::isfinite (v))
          return bad ("VIEWPOINT value '" + printable (tok[i]) + "' is not a finite number");
      }
    }
    else if (key == "DATA")
    {
      has_data = true;
      if (nargs != 1 || (tok[1] != "ascii" && tok[1] != "binary" && tok[1] != "binary_compressed"))
        return bad ("DATA must be ascii, binary or binary_compressed");
      h.data = tok[1];
      h.header_len = pos;
    }
    else
    {
      const bool is_text = std::all_of (key.begin (), key.end (), [] (char c) { return c >= 32 && c < 127; });
      error = where + (is_text ? "not a PCD file: unexpected header line starting with '" + printable (key) + "'"
                               : std::string ("not a PCD file: binary data where the header should be"));
      return false;
    }
  }

  if (!has_fields)
    return error = where + "invalid PCD header: no FIELDS line", false;
  if (!has_size)
    return error = where + "invalid PCD header: no SIZE line", false;
  if (!has_type)
    return error = where + "invalid PCD header: no TYPE line", false;
  if (!has_width)
    return error = where + "invalid PCD header: no WIDTH line", false;
  if (!has_points)
    return error = where + "invalid PCD header: no POINTS line", false;
  const std::size_t nf = h.names.size ();
  if (!has_count)
    h.counts.assign (nf, 1);
  if (h.sizes.size () != nf || h.types.size () != nf || h.counts.size () != nf)
  {
    error = where + "invalid PCD header: FIELDS lists " + std::to_string (nf) + " names but SIZE has " +
            std::to_string (h.sizes.size ()) + ", TYPE " + std::to_string (h.types.size ()) +
            " and COUNT " + std::to_string (h.counts.size ()) + " entries";
    return false;
  }
  for (std::size_t i = 0; i < nf; ++i)
  {
    if (h.types[i] == 'F' && h.sizes[i] != 4 && h.sizes[i] != 8)
    {
      error = where + "invalid PCD header: field '" + printable (h.names[i]) + "' is TYPE F with SIZE " +
              std::to_string (h.sizes[i]) + " (only 4 or 8)";
      return false;
    }
    h.point_size += h.sizes[i] * h.counts[i];
    h.values_per_point += h.counts[i];
  }
  for (const char* axis : {"x", "y", "z"})
  {
    if (require_xyz && std::find (h.names.begin (), h.names.end (), axis) == h.names.end ())
    {
      error = where + "the cloud has no '" + axis + "' field (FIELDS:";
      for (std::size_t i = 0; i < nf && i < 12; ++i)
        error += " " + printable (h.names[i]);
      error += nf > 12 ? " ...)" : ")";
      return false;
    }
  }
  if (!has_height)
    h.height = 1;
  if (h.width * h.height != h.points)
  {
    error = where + "invalid PCD header: POINTS " + std::to_string (h.points) + " != WIDTH " +
            std::to_string (h.width) + " x HEIGHT " + std::to_string (h.height);
    return false;
  }
  if (h.points == 0)
  {
    error = where + "the cloud has no points";
    return false;
  }
  return true;
}

/** \brief Check the data section against the header. */
bool
checkPcdBody (const std::string& path, const PcdHeader& h, std::uint64_t file_size, std::string& error)
{
  const std::string where = path + ": ";
  const std::uint64_t available = file_size - h.header_len;
  if (h.data == "binary")
  {
    // Divide instead of multiplying: POINTS * point_size may overflow for a lying header.
    if (h.points > available / h.point_size)
    {
      error = where + "truncated binary PCD: the header promises " + std::to_string (h.points) +
              " points of " + std::to_string (h.point_size) + " bytes but only " +
              std::to_string (available) + " data bytes follow";
      return false;
    }
    return true;
  }
  if (h.data == "binary_compressed")
  {
    std::ifstream in (path, std::ios::binary);
    std::uint32_t sizes[2] = {0, 0};
    if (available < 8 || !in.seekg (static_cast<std::streamoff> (h.header_len)) ||
        !in.read (reinterpret_cast<char*> (sizes), 8))
    {
      error = where + "truncated binary_compressed PCD: no block sizes after the header";
      return false;
    }
    const std::uint64_t compressed = sizes[0], uncompressed = sizes[1];
    if (h.points > std::numeric_limits<std::uint32_t>::max () / h.point_size ||
        uncompressed != h.points * h.point_size)
    {
      error = where + "corrupt binary_compressed PCD: the block decompresses to " +
              std::to_string (uncompressed) + " bytes, but " + std::to_string (h.points) +
              " points of " + std::to_string (h.point_size) + " bytes are promised";
      return false;
    }
    if (compressed == 0 || compressed > available - 8)
    {
      error = where + "corrupt binary_compressed PCD: the compressed block claims " +
              std::to_string (compressed) + " bytes, the file holds " + std::to_string (available - 8);
      return false;
    }
    // Decompress once here: PCL only warns about an inconsistent stream and carries on.
    std::vector<char> packed (compressed);
    if (!in.read (packed.data (), static_cast<std::streamsize> (compressed)))
    {
      error = where + "cannot read the compressed block: " + std::strerror (errno);
      return false;
    }
    std::vector<char> unpacked (uncompressed);
    const unsigned int got = pcl::lzfDecompress (packed.data (), static_cast<unsigned int> (compressed),
                                                 unpacked.data (), static_cast<unsigned int> (uncompressed));
    if (got != uncompressed)
    {
      error = where + "corrupt binary_compressed PCD: the LZF block does not decompress to " +
              std::to_string (uncompressed) + " bytes";
      return false;
    }
    return true;
  }
  // ascii: PCL reads one point per non-empty line and throws (std::out_of_range, which it does not
  // catch) on a line with too few values, so check both here.
  std::ifstream in (path, std::ios::binary);
  if (!in.seekg (static_cast<std::streamoff> (h.header_len)))
  {
    error = where + "cannot read the data section";
    return false;
  }
  std::string line;
  std::uint64_t rows = 0;
  while (rows < h.points && std::getline (in, line))
  {
    if (line.empty ())
      continue;
    // Count tokens without allocating them.
    std::uint64_t values = 0;
    bool in_token = false;
    for (const char c : line)
    {
      const bool blank = c == ' ' || c == '\t' || c == '\r';
      if (!blank && !in_token)
        ++values;
      in_token = !blank;
    }
    if (values < h.values_per_point)
    {
      error = where + "ascii PCD data row " + std::to_string (rows + 1) + " has " + std::to_string (values) +
              " values, the header promises " + std::to_string (h.values_per_point);
      return false;
    }
    ++rows;
  }
  if (rows < h.points)
  {
    error = where + "truncated ascii PCD: the header promises " + std::to_string (h.points) +
            " points but only " + std::to_string (rows) + " data rows follow";
    return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// PLY header check
// ---------------------------------------------------------------------------------------------

struct PlyProperty
{
  std::string name;
  bool is_list = false;
  std::uint64_t size = 0;       ///< scalar size, or size of a list's items
  std::uint64_t count_size = 0; ///< size of a list's length prefix
  bool is_uchar = false;        ///< scalar of type uchar / uint8 (PCL treats some names specially)
};

struct PlyElement
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

std::uint64_t
plyTypeSize (const std::string& t)
{
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8")
    return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16")
    return 2;
  if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32")
    return 4;
  if (t == "double" || t == "float64")
    return 8;
  return 0;
}

bool
checkPly (const std::string& path, const std::string& text, std::uint64_t file_size,
          std::uint64_t& vertex_count, bool& has_range_grid, std::string& format, std::string& error)
{
  const std::string where = path + ": ";
  std::size_t pos = 0;
  std::string line;
  if (!nextLine (text, pos, line) || tokenize (line) != std::vector<std::string>{"ply"})
  {
    error = where + "not a PLY file: it does not start with 'ply'";
    return false;
  }
  std::vector<PlyElement> elements;
  std::uint64_t grid_cols = 0, grid_rows = 0;
  bool ended = false;
  std::size_t line_no = 1;
  while (!ended)
  {
    if (!nextLine (text, pos, line))
    {
      error = where + "invalid PLY header: no end_header line";
      return false;
    }
    ++line_no;
    const std::vector<std::string> tok = tokenize (line);
    const auto bad = [&] (const std::string& what) {
      error = where + "invalid PLY header: " + what + " (line " + std::to_string (line_no) + ")";
      return false;
    };
    if (tok.empty () || tok[0] == "comment")
      continue;
    // PCL splits an obj_info line itself and asserts that it starts with the keyword.
    if (line[0] == ' ' || line[0] == '\t')
      return bad ("line starts with a blank");
    if (tok[0] == "obj_info")
    {
      // PCL sizes its buffer from num_cols x num_rows when given: they must match the vertices.
      if (tok.size () >= 3 && (tok[1] == "num_cols" || tok[1] == "num_rows"))
      {
        std::uint64_t v = 0;
        if (!parseUnsigned (tok[2], v) || v == 0 || v > std::numeric_limits<std::uint32_t>::max ())
          return bad ("obj_info " + tok[1] + " needs a positive number");
        (tok[1] == "num_cols" ? grid_cols : grid_rows) = v;
      }
      continue;
    }
    if (tok[0] == "format")
    {
      if (!format.empty ())
        return bad ("format appears twice");
      if (tok.size () != 3 || (tok[1] != "ascii" && tok[1] != "binary_little_endian" &&
                               tok[1] != "binary_big_endian"))
        return bad ("unknown format");
      if (tok[2] != "1.0")
        return bad ("format version '" + printable (tok[2]) + "' is not 1.0");
      format = tok[1];
    }
    else if (tok[0] == "element")
    {
      PlyElement e;
      if (tok.size () != 3 || !parseUnsigned (tok[2], e.count) ||
          e.count > std::numeric_limits<std::uint32_t>::max ())
        return bad ("element needs a name and a count");
      e.name = tok[1];
      elements.push_back (e);
    }
    else if (tok[0] == "property")
    {
      if (elements.empty ())
        return bad ("property before any element");
      PlyProperty p;
      if (tok.size () == 5 && tok[1] == "list")
      {
        p.is_list = true;
        p.count_size = plyTypeSize (tok[2]);
        p.size = plyTypeSize (tok[3]);
        p.name = tok[4];
        if (p.count_size == 0 || p.size == 0)
          return bad ("unknown list type");
      }
      else if (tok.size () == 3)
      {
        p.size = plyTypeSize (tok[1]);
        p.is_uchar = tok[1] == "uchar" || tok[1] == "uint8";
        p.name = tok[2];
        if (p.size == 0)
          return bad ("unknown property type '" + printable (tok[1]) + "'");
      }
      else
        return bad ("malformed property line");
      if (elements.back ().properties.size () >= kMaxFields)
        return bad ("too many properties");
      elements.back ().properties.push_back (p);
    }
    else if (tok[0] == "end_header")
      ended = true;
    else
      return bad ("unexpected line starting with '" + printable (tok[0]) + "'");
  }
  if (format.empty ())
    return error = where + "invalid PLY header: no format line", false;

  const PlyElement* vertex = nullptr;
  has_range_grid = false;
  for (const auto& e : elements)
  {
    if (e.name == "vertex" && vertex)
      return error = where + "invalid PLY header: two vertex elements", false;
    if (e.name == "vertex")
      vertex = &e;
    if (e.name == "range_grid")
      has_range_grid = true;
  }
  if (!vertex || vertex->count == 0)
    return error = where + "the PLY file has no vertices", false;
  // The checks below keep PCL 1.13's PLY reader on layouts it handles: its callbacks assert
  // (abort) when its buffer and the properties disagree.
  if (has_range_grid)
    return error = where + "PLY range grids (organized scans) are not supported; convert to PCD", false;
  if ((grid_cols || grid_rows) && grid_cols * grid_rows != vertex->count)
    return error = where + "PLY obj_info num_cols x num_rows does not match the vertex count", false;
  bool colour_seen = false, alpha_seen = false;
  const auto& props = vertex->properties;
  for (std::size_t j = 0; j < props.size (); ++j)
  {
    const PlyProperty& p = props[j];
    if (p.is_list)
      return error = where + "PLY vertex list properties ('" + printable (p.name) + "') are not supported", false;
    if (!p.is_uchar)
      continue;
    // uchar colours: PCL packs red, green, blue into one rgb field and expects them in a row.
    const bool plain = p.name == "red" || p.name == "green" || p.name == "blue";
    const bool diffuse = p.name == "diffuse_red" || p.name == "diffuse_green" || p.name == "diffuse_blue";
    if (plain || diffuse)
    {
      const std::string prefix = diffuse ? "diffuse_" : "";
      const bool triple = !colour_seen && p.name == prefix + "red" && j + 2 < props.size () &&
                          props[j + 1].is_uchar && props[j + 1].name == prefix + "green" &&
                          props[j + 2].is_uchar && props[j + 2].name == prefix + "blue";
      if (!triple)
        return error = where + "unsupported PLY colour layout: uchar red, green, blue must appear once, in this order", false;
      colour_seen = true;
      j += 2;
    }
    else if (p.name == "alpha")
    {
      if (!colour_seen || alpha_seen)
        return error = where + "unsupported PLY colour layout: uchar alpha needs red, green, blue before it", false;
      alpha_seen = true;
    }
  }
  for (const char* axis : {"x", "y", "z"})
  {
    bool found = false;
    for (const auto& p : vertex->properties)
      found = found || (p.name == axis && !p.is_list);
    if (!found)
      return error = where + "the PLY vertices have no '" + axis + "' property", false;
  }
  vertex_count = vertex->count;

  // The body must be at least as long as every element with empty lists.
  const std::uint64_t available = file_size - pos;
  if (format == "ascii")
  {
    std::uint64_t needed = 0;
    for (const auto& e : elements)
      needed += e.count * e.properties.size ();
    std::ifstream in (path, std::ios::binary);
    in.seekg (static_cast<std::streamoff> (pos));
    std::uint64_t values = 0;
    bool in_token = false;
    char buffer[65536];
    while (values < needed && in)
    {
      in.read (buffer, sizeof (buffer));
      const std::streamsize got = in.gcount ();
      for (std::streamsize i = 0; i < got; ++i)
      {
        const char c = buffer[i];
        const bool blank = c == ' ' || c == '\t' || c == '\r' || c == '\n';
        if (!blank && !in_token)
          ++values;
        in_token = !blank;
      }
    }
    if (values < needed)
    {
      error = where + "truncated ascii PLY: the header promises at least " + std::to_string (needed) +
              " values, the file holds " + std::to_string (values);
      return false;
    }
    return true;
  }
  long double needed = 0.0L;  // long double: counts times sizes of a lying header may overflow 64 bits
  for (const auto& e : elements)
  {
    std::uint64_t per_item = 0;
    for (const auto& p : e.properties)
      per_item += p.is_list ? p.count_size : p.size;
    needed += static_cast<long double> (e.count) * static_cast<long double> (per_item);
  }
  if (needed > static_cast<long double> (available))
  {
    error = where + "truncated binary PLY: the header promises at least " +
            std::to_string (static_cast<unsigned long long> (needed)) + " data bytes, the file holds " +
            std::to_string (available);
    return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// Blob checks and typed views
// ---------------------------------------------------------------------------------------------

/** \brief The blob as PCL returned it must be addressable as width x height points. */
bool
checkBlobLayout (const pcl::PCLPointCloud2& blob, std::string& error)
{
  const std::uint64_t w = blob.width, h = blob.height;
  if (w == 0 || h == 0)
  {
    error = "the cloud has no points";
    return false;
  }
  for (const auto& f : blob.fields)
  {
    const std::uint64_t end = f.offset + static_cast<std::uint64_t> (f.count) * datatypeSize (f.datatype);
    if (datatypeSize (f.datatype) == 0 || end > blob.point_step)
    {
      error = "the reader returned an inconsistent field '" + printable (f.name) + "'";
      return false;
    }
  }
  if (blob.row_step < w * blob.point_step ||
      static_cast<std::uint64_t> (blob.data.size ()) < (h - 1) * blob.row_step + w * blob.point_step)
  {
    error = "the reader returned less data than width x height points";
    return false;
  }
  return true;
}

/** \brief Read one scalar field of every point as float (element 0 of the field). */
void
extractField (const pcl::PCLPointCloud2& blob, const pcl::PCLPointField& f, std::vector<float>& values)
{
  values.resize (static_cast<std::size_t> (blob.width) * blob.height);
  std::size_t i = 0;
  for (std::uint32_t row = 0; row < blob.height; ++row)
  {
    const std::uint8_t* p = blob.data.data () + static_cast<std::size_t> (row) * blob.row_step + f.offset;
    for (std::uint32_t col = 0; col < blob.width; ++col, ++i, p += blob.point_step)
      values[i] = static_cast<float> (readScalar (p, f.datatype));
  }
}

/** \brief Fill the typed views. Fields of any numeric type are converted, unlike
  * pcl::fromPCLPointCloud2, which leaves a double-precision x at zero. */
void
buildViews (LoadedCloud& c)
{
  const std::size_t n = c.size ();
  std::vector<float> x, y, z;
  extractField (c.blob, *findField (c.blob, "x"), x);
  extractField (c.blob, *findField (c.blob, "y"), y);
  extractField (c.blob, *findField (c.blob, "z"), z);
  c.xyz.reset (new pcl::PointCloud<pcl::PointXYZ>);
  c.xyz->header = c.blob.header;
  c.xyz->width = c.blob.width;
  c.xyz->height = c.blob.height;
  c.xyz->points.resize (n);
  bool dense = true;
  for (std::size_t i = 0; i < n; ++i)
  {
    pcl::PointXYZ& p = (*c.xyz)[i];
    p.x = x[i];
    p.y = y[i];
    p.z = z[i];
    dense = dense && std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z);
  }
  c.xyz->is_dense = dense;
  c.xyz->sensor_origin_ = c.origin;
  c.xyz->sensor_orientation_ = c.orientation;

  const pcl::PCLPointField* nx = findField (c.blob, "normal_x");
  const pcl::PCLPointField* ny = findField (c.blob, "normal_y");
  const pcl::PCLPointField* nz = findField (c.blob, "normal_z");
  c.normals.reset ();
  if (nx && ny && nz)
  {
    extractField (c.blob, *nx, x);
    extractField (c.blob, *ny, y);
    extractField (c.blob, *nz, z);
    std::vector<float> curvature (n, 0.0f);
    if (const pcl::PCLPointField* cf = findField (c.blob, "curvature"))
      extractField (c.blob, *cf, curvature);
    c.normals.reset (new pcl::PointCloud<pcl::Normal>);
    c.normals->header = c.blob.header;
    c.normals->width = c.blob.width;
    c.normals->height = c.blob.height;
    c.normals->points.resize (n);
    bool ndense = true;
    for (std::size_t i = 0; i < n; ++i)
    {
      pcl::Normal& q = (*c.normals)[i];
      q.normal_x = x[i];
      q.normal_y = y[i];
      q.normal_z = z[i];
      q.curvature = curvature[i];
      ndense = ndense && std::isfinite (q.normal_x) && std::isfinite (q.normal_y) && std::isfinite (q.normal_z);
    }
    c.normals->is_dense = ndense;
    c.normals->sensor_origin_ = c.origin;
    c.normals->sensor_orientation_ = c.orientation;
  }
}

bool
loadPcd (const std::string& path, std::uint64_t file_size, LoadedCloud& c, std::string& error,
         bool require_xyz = true)
{
  std::string text;
  if (!readPrefix (path, kMaxHeaderBytes, text, error))
    return false;
  PcdHeader h;
  if (!parsePcdHeader (path, text, file_size, h, error, require_xyz) || !checkPcdBody (path, h, file_size, error))
    return false;
  // PCL's reader parses on after DATA while lines look like header lines (see writeLabeledCloud):
  // such a file would be read with a header other than the one just checked.
  if (h.header_len < text.size () &&
      pcdDataMisreadAsHeader (std::vector<std::uint8_t> (text.begin () + static_cast<std::ptrdiff_t> (h.header_len), text.end ())))
    return error = path + ": the data begins with bytes that PCL's reader takes for a header line; it cannot "
                          "read this file correctly", false;
  pcl::PCDReader reader;
  int version = 0;
  const int rc = reader.read (path, c.blob, c.origin, c.orientation, version, 0);
  if (rc != 0)
  {
    error = path + ": PCL could not read the PCD file (code " + std::to_string (rc) + ")";
    return false;
  }
  std::string layout_error;
  if (!checkBlobLayout (c.blob, layout_error))
  {
    error = path + ": " + layout_error;
    return false;
  }
  if (static_cast<std::uint64_t> (c.blob.width) * c.blob.height != h.points)
  {
    error = path + ": PCL read " + std::to_string (c.size ()) + " points, the header promises " +
            std::to_string (h.points);
    return false;
  }
  if (require_xyz)
    for (const char* axis : {"x", "y", "z"})
      if (!findField (c.blob, axis))
        return error = path + std::string (": PCL returned no '") + axis + "' field", false;
  c.format = "pcd " + h.data;
  return true;
}

bool
loadPly (const std::string& path, std::uint64_t file_size, LoadedCloud& c, std::string& error)
{
  std::string text;
  if (!readPrefix (path, kMaxHeaderBytes, text, error))
    return false;
  std::uint64_t vertices = 0;
  bool range_grid = false;
  std::string format;
  if (!checkPly (path, text, file_size, vertices, range_grid, format, error))
    return false;
  pcl::PLYReader reader;
  int version = 0;
  const int rc = reader.read (path, c.blob, c.origin, c.orientation, version, 0);
  if (rc != 0)
  {
    error = path + ": PCL could not read the PLY file (code " + std::to_string (rc) + ")";
    return false;
  }
  std::string layout_error;
  if (!checkBlobLayout (c.blob, layout_error))
  {
    error = path + ": " + layout_error;
    return false;
  }
  // Camera viewport values can resize the cloud after the vertices were read.
  if (c.size () != vertices)
  {
    error = path + ": PCL read " + std::to_string (c.size ()) + " points, the header promises " +
            std::to_string (vertices);
    return false;
  }
  for (const char* axis : {"x", "y", "z"})
    if (!findField (c.blob, axis))
      return error = path + std::string (": PCL returned no '") + axis + "' field", false;
  c.format = "ply " + format;
  return true;
}

/** Path names a non-empty regular file; its size. */
bool
checkInputFile (const std::string& path, std::uint64_t& file_size, std::string& error)
{
  struct stat st;
  if (path.empty ())
    return error = "no input file given", false;
  if (::stat (path.c_str (), &st) != 0)
    return error = path + ": " + (errno == ENOENT ? std::string ("no such file") : std::strerror (errno)), false;
  if (S_ISDIR (st.st_mode))
    return error = path + ": is a directory, not a point cloud file", false;
  if (!S_ISREG (st.st_mode))
    return error = path + ": not a regular file", false;
  if (st.st_size == 0)
    return error = path + ": the file is empty", false;
  file_size = static_cast<std::uint64_t> (st.st_size);
  return true;
}

/** \brief A label / colour slot of the output point. */
enum class Slot
{
  Copy,
  Label,
  Rgb,
  Rgba
};
} // namespace

// -----------------------------------------------------------------------------------------------
bool
loadPcdBlob (const std::string& path, pcl::PCLPointCloud2& blob, std::string& error)
{
  error.clear ();
  std::uint64_t file_size = 0;
  if (!checkInputFile (path, file_size, error))
    return false;
  LoadedCloud c;
  try
  {
    if (!loadPcd (path, file_size, c, error, false))
      return false;
  }
  catch (const std::exception& e)
  {
    return error = path + ": cannot read the file: " + printable (e.what ()), false;
  }
  blob = std::move (c.blob);
  return true;
}

// -----------------------------------------------------------------------------------------------
bool
loadCloud (const std::string& path, LoadedCloud& out, std::string& error)
{
  out = LoadedCloud ();
  error.clear ();
  std::uint64_t file_size = 0;
  if (!checkInputFile (path, file_size, error))
    return false;

  std::string ext = extensionOf (path);
  if (ext != "pcd" && ext != "ply")
  {
    // Unknown extension: decide by the first bytes.
    std::string head;
    if (!readPrefix (path, 4, head, error))
      return false;
    ext = (head.compare (0, 3, "ply") == 0 && head.size () == 4 && (head[3] == '\n' || head[3] == '\r'))
              ? "ply" : "pcd";
  }

  LoadedCloud c;
  try
  {
    const bool ok = ext == "ply" ? loadPly (path, file_size, c, error) : loadPcd (path, file_size, c, error);
    if (!ok)
      return false;
    buildViews (c);
  }
  catch (const std::bad_alloc&)
  {
    error = path + ": not enough memory to read the cloud";
    return false;
  }
  catch (const std::exception& e)
  {
    error = path + ": cannot read the cloud: " + printable (e.what ());
    return false;
  }
  catch (...)
  {
    error = path + ": cannot read the cloud (unknown error)";
    return false;
  }
  out = std::move (c);
  return true;
}

// -----------------------------------------------------------------------------------------------
void
makeLoadedCloud (const pcl::PointCloud<pcl::PointXYZ>& cloud, LoadedCloud& out)
{
  out = LoadedCloud ();
  pcl::toPCLPointCloud2 (cloud, out.blob);
  out.origin = cloud.sensor_origin_;
  out.orientation = cloud.sensor_orientation_;
  out.format = "memory";
  buildViews (out);
}

// -----------------------------------------------------------------------------------------------
std::size_t
countFinite (const pcl::PointCloud<pcl::PointXYZ>& cloud)
{
  std::size_t n = 0;
  for (const auto& p : cloud.points)
    if (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z))
      ++n;
  return n;
}

// -----------------------------------------------------------------------------------------------
bool
pcdDataMisreadAsHeader (const std::vector<std::uint8_t>& data)
{
  // What pcl::PCDReader::readHeader (PCL 1.13) does after the DATA line: read a line (up to '\n'),
  // skip it if it is empty, take its first whitespace-delimited token, skip the line if that
  // starts with '#', treat it as a header line if it starts with a keyword, and stop otherwise.
  static const char* const kKeywords[] = {"VERSION", "FIELDS", "COLUMNS", "SIZE", "TYPE", "COUNT",
                                          "WIDTH", "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};
  const auto space = [] (std::uint8_t c) { return c == ' ' || (c >= '\t' && c <= '\r'); };
  std::size_t pos = 0;
  while (pos < data.size ())
  {
    std::size_t eol = pos;
    while (eol < data.size () && data[eol] != '\n')
      ++eol;
    const std::size_t line_begin = pos;
    pos = eol + 1;
    if (eol == line_begin)
      continue; // empty line
    std::size_t t = line_begin;
    while (t < eol && space (data[t]))
      ++t;
    std::size_t t_end = t;
    while (t_end < eol && !space (data[t_end]))
      ++t_end;
    if (t == t_end)
      return false; // whitespace only: no keyword, the header ends
    const std::string token (data.begin () + static_cast<std::ptrdiff_t> (t),
                             data.begin () + static_cast<std::ptrdiff_t> (t_end));
    if (token[0] == '#')
      continue; // a comment line: the next line is read too
    for (const char* k : kKeywords)
      if (token.compare (0, std::strlen (k), k) == 0)
        return true;
    return false;
  }
  return false;
}

// -----------------------------------------------------------------------------------------------
bool
writeLabeledCloud (const std::string& path, const LoadedCloud& in,
                   const std::vector<std::uint32_t>& labels, std::string& error)
{
  error.clear ();
  const pcl::PCLPointCloud2& src = in.blob;
  const std::size_t n = in.size ();
  if (n == 0)
    return error = path + ": nothing to write: the cloud has no points", false;
  if (labels.size () != n)
  {
    error = path + ": " + std::to_string (labels.size ()) + " labels for " + std::to_string (n) + " points";
    return false;
  }
  std::string layout_error;
  if (!checkBlobLayout (src, layout_error))
    return error = path + ": cannot write the cloud: " + layout_error, false;

  // Output fields: the input's in order (padding "_" dropped, since the writer re-pads anyway),
  // label and colour fields re-typed in place, missing ones appended. Packed without gaps.
  // \a front moves the label (bit 0) and the colour (bit 1) to the front instead: see below.
  pcl::PCLPointCloud2 dst;
  const auto build = [&] (int front) {
    dst = pcl::PCLPointCloud2 ();
    std::vector<Slot> slots;
    std::vector<const pcl::PCLPointField*> sources;
    std::uint32_t offset = 0;
    const auto add = [&] (const std::string& name, std::uint8_t datatype, std::uint32_t count, Slot slot,
                          const pcl::PCLPointField* source) {
      pcl::PCLPointField f;
      f.name = name;
      f.datatype = datatype;
      f.count = count;
      f.offset = offset;
      offset += static_cast<std::uint32_t> (count * datatypeSize (datatype));
      dst.fields.push_back (f);
      slots.push_back (slot);
      sources.push_back (source);
    };
    std::string colour_name = "rgb";
    for (const auto& f : src.fields)
      if (f.name == "rgba" || f.name == "rgb")
      {
        colour_name = f.name;
        break;
      }
    const auto add_label = [&] { add ("label", pcl::PCLPointField::UINT32, 1, Slot::Label, nullptr); };
    const auto add_colour = [&] {
      if (colour_name == "rgba")
        add ("rgba", pcl::PCLPointField::UINT32, 1, Slot::Rgba, nullptr);
      else
        add ("rgb", pcl::PCLPointField::FLOAT32, 1, Slot::Rgb, nullptr);
    };
    // A field moved to the front is not repeated at its place; any other label or colour field is
    // re-typed in place, as without moving.
    bool label_moved = (front & 1) != 0, colour_moved = (front & 2) != 0;
    bool has_label = label_moved, has_colour = colour_moved;
    if (label_moved)
      add_label ();
    if (colour_moved)
      add_colour ();
    for (const auto& f : src.fields)
    {
      if (f.name == "_")
        continue;
      if (f.name == "label")
      {
        if (label_moved)
          label_moved = false;
        else
          add_label ();
        has_label = true;
      }
      else if (f.name == "rgb" || f.name == "rgba")
      {
        if (colour_moved && f.name == colour_name)
          colour_moved = false;
        else if (f.name == "rgba")
          add ("rgba", pcl::PCLPointField::UINT32, 1, Slot::Rgba, nullptr);
        else
          add ("rgb", pcl::PCLPointField::FLOAT32, 1, Slot::Rgb, nullptr);
        has_colour = true;
      }
      else
        add (f.name, f.datatype, f.count, Slot::Copy, &f);
    }
    if (!has_label)
      add_label ();
    if (!has_colour)
      add_colour ();

    dst.header = src.header;
    dst.width = src.width;
    dst.height = src.height;
    dst.is_bigendian = false;
    dst.is_dense = src.is_dense;
    dst.point_step = offset;
    dst.row_step = offset * src.width;
    dst.data.resize (static_cast<std::size_t> (dst.row_step) * dst.height);

    std::size_t i = 0;
    for (std::uint32_t row = 0; row < src.height; ++row)
    {
      for (std::uint32_t col = 0; col < src.width; ++col, ++i)
      {
        const std::uint8_t* sp =
            src.data.data () + static_cast<std::size_t> (row) * src.row_step + static_cast<std::size_t> (col) * src.point_step;
        std::uint8_t* dp = dst.data.data () + i * dst.point_step;
        const auto colour = labelColour (labels[i]);
        // PCL's packed colour: 0xAARRGGBB, alpha opaque.
        const std::uint32_t packed = (0xFFu << 24) | (static_cast<std::uint32_t> (colour[0]) << 16) |
                                     (static_cast<std::uint32_t> (colour[1]) << 8) | colour[2];
        for (std::size_t k = 0; k < dst.fields.size (); ++k)
        {
          const pcl::PCLPointField& df = dst.fields[k];
          switch (slots[k])
          {
            case Slot::Copy:
              std::memcpy (dp + df.offset, sp + sources[k]->offset, df.count * datatypeSize (df.datatype));
              break;
            case Slot::Label:
              std::memcpy (dp + df.offset, &labels[i], 4);
              break;
            case Slot::Rgb:
            case Slot::Rgba:
              std::memcpy (dp + df.offset, &packed, 4);
              break;
          }
        }
      }
    }
  };

  try
  {
    // PCL's reader keeps parsing header lines after DATA as long as they look like header lines:
    // binary data whose first bytes read as "DATA", "SIZE", "VIEWPOINT"... (after any comment or
    // empty lines) makes the file unreadable (found by fuzz_cloud_reader; "DATA" even makes PCL
    // throw). Such data is rare (the first point's bytes must spell a keyword), and then another
    // field goes first: the label (a small integer) or the colour.
    int front = 0;
    build (front);
    while (pcdDataMisreadAsHeader (dst.data) && front < 3)
      build (++front);
    if (pcdDataMisreadAsHeader (dst.data))
      return error = path + ": cannot write the cloud: every field order of its first point reads as a PCD header line", false;
  }
  catch (const std::bad_alloc&)
  {
    return error = path + ": not enough memory to build the labelled cloud", false;
  }

  std::string tmp;
  if (!createTempFileFor (path, tmp, error))
    return false;
  int rc = -1;
  std::string what;
  try
  {
    pcl::PCDWriter writer;
    rc = writer.writeBinary (tmp, dst, in.origin, in.orientation);
  }
  catch (const std::exception& e)
  {
    what = printable (e.what ());
  }
  catch (...)
  {
    what = "unknown error";
  }
  if (rc != 0)
  {
    discardTempFile (tmp);
    error = path + ": writing the PCD file failed" + (what.empty () ? std::string () : ": " + what);
    return false;
  }
  return commitTempFile (tmp, path, error);
}

// -----------------------------------------------------------------------------------------------
bool
createTempFileFor (const std::string& path, std::string& tmp_path, std::string& error)
{
  struct stat st;
  if (path.empty ())
    return error = "empty output file name", false;
  if (::stat (path.c_str (), &st) == 0 && S_ISDIR (st.st_mode))
    return error = path + ": is a directory, cannot write a file there", false;
  std::vector<char> name (path.begin (), path.end ());
  const char suffix[] = ".tmp-XXXXXX";
  name.insert (name.end (), suffix, suffix + sizeof (suffix));  // includes the terminating NUL
  const int fd = ::mkstemp (name.data ());
  if (fd < 0)
  {
    error = path + ": cannot create the file: " + std::strerror (errno);
    return false;
  }
  // mkstemp creates 0600; give the result the permissions an ordinary new file would get.
  // umask can only be read by setting it, hence the two calls.
  const mode_t mask = ::umask (022);
  ::umask (mask);
  (void) ::fchmod (fd, static_cast<mode_t> (0666) & ~mask);
  ::close (fd);
  tmp_path.assign (name.data ());
  return true;
}

bool
commitTempFile (const std::string& tmp_path, const std::string& path, std::string& error)
{
  if (::rename (tmp_path.c_str (), path.c_str ()) != 0)
  {
    error = path + ": cannot move the finished file into place: " + std::strerror (errno);
    discardTempFile (tmp_path);
    return false;
  }
  return true;
}

void
discardTempFile (const std::string& tmp_path)
{
  if (!tmp_path.empty ())
    (void) ::unlink (tmp_path.c_str ());
}

bool
writeFileAtomically (const std::string& path, const std::string& content, std::string& error)
{
  std::string tmp;
  if (!createTempFileFor (path, tmp, error))
    return false;
  std::FILE* f = std::fopen (tmp.c_str (), "wb");
  if (!f)
  {
    error = path + ": cannot write: " + std::strerror (errno);
    discardTempFile (tmp);
    return false;
  }
  const bool written = std::fwrite (content.data (), 1, content.size (), f) == content.size ();
  const int saved_errno = errno;
  const bool closed = std::fclose (f) == 0;
  if (!written || !closed)
  {
    error = path + ": cannot write: " + std::strerror (written ? errno : saved_errno);
    discardTempFile (tmp);
    return false;
  }
  return commitTempFile (tmp, path, error);
}

bool
checkWritable (const std::string& path, std::string& error)
{
  std::string tmp;
  if (!createTempFileFor (path, tmp, error))
    return false;
  discardTempFile (tmp);
  return true;
}

} // namespace rspd_tools
