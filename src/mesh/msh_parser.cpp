// The .msh syntax, as documented in the Gmsh reference manual ("MSH file format",
// versions 4.1 and 2.2). Binary files store numbers in the writer's byte order, which
// the header's integer 1 identifies; only little-endian files (every x86 and ARM
// writer) are read. In 4.1 binary files counts and tags are 8-byte size_t, entity
// and element-type fields 4-byte int, and so are the element tags of $ElementData; in
// 2.2 binary files all integers are 4-byte int.
#include "mesh/msh_parser.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>

#include "core/errors.hpp"
#include "core/printable.hpp"

namespace tunica {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

class Parser {
public:
  Parser(std::string_view bytes, const std::string& path, bool lines)
      : b_(bytes), path_(path), lines_known_(lines), section_line_known_(lines) {}

  MshFile parse() {
    header();
    std::set<std::string> seen;
    for (;;) {
      skip_space();  // between sections: text, also in binary files
      const int at = line_;
      const std::string_view t = token();
      if (t.empty()) break;
      if (t[0] != '$')
        fail(fmt::format("expected the start of a section ($Nodes, $Elements, ...), found '{}'", printable(t)), at);
      const std::string name(t.substr(1));
      // fmt::format, not "$" + printable(...): GCC 12 warns falsely on that (-Wrestrict, GCC bug 105651).
      section_ = fmt::format("${}", printable(name));
      section_line_ = at;
      if (name == "Nodes" || name == "Elements" || name == "Entities" || name == "PhysicalNames") {
        if (!seen.insert(name).second) fail(fmt::format("the file has a second {} section", section_), at);
      }
      if (name == "PhysicalNames") physical_names();
      else if (name == "Entities" && v4()) entities();
      else if (name == "Nodes") v4() ? nodes4() : nodes2();
      else if (name == "Elements") v4() ? elements4() : elements2();
      else if (name == "ElementData") element_data();
      else if (name == "PartitionedEntities")
        fail("a partitioned mesh is not read: save it unpartitioned (Gmsh API: gmsh::model::mesh::unpartition())", at);
      else if (name.rfind("End", 0) == 0) fail(fmt::format("{} without its opening section", section_), at);
      else skip_section(name);
      section_.clear();
    }
    if (!seen.count("Nodes")) fail("the file has no $Nodes section", 0);
    if (!seen.count("Elements")) fail("the file has no $Elements section", 0);
    return std::move(f_);
  }

private:
  bool v4() const { return f_.version >= 4; }

  // ---------------------------------------------------------------- errors
  [[noreturn]] void fail(const std::string& what, int line = -1) const {
    const int l = !section_line_known_ ? 0 : line >= 0 ? line : (lines_known_ ? line_ : 0);
    std::string where;
    if (!section_.empty()) where = (l == 0 && section_line_ > 0 && section_line_known_ ? fmt::format(" (in {} from line {})", section_, section_line_)
                                                                 : fmt::format(" (in {})", section_));
    throw InputError(SourceLocation{path_, l, 0, ""}, what + where);
  }

  // ---------------------------------------------------------------- ASCII tokens
  void skip_space() {
    while (pos_ < b_.size() && is_space(b_[pos_])) {
      if (b_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  /// The next whitespace-delimited token; empty at the end of the file.
  std::string_view token() {
    skip_space();
    const std::size_t start = pos_;
    while (pos_ < b_.size() && !is_space(b_[pos_])) ++pos_;
    return b_.substr(start, pos_ - start);
  }
  std::string_view required_token(const std::string& what) {
    const std::string_view t = token();
    if (t.empty()) fail("the file ends where " + what + " was expected: it is cut short, or a count before is too large");
    return t;
  }
  long integer(const std::string& what, long lo, long hi) {
    const std::string_view t = required_token(what);
    long v = 0;
    const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || p != t.data() + t.size())
      fail(fmt::format("expected {} (an integer), found '{}'", what, printable(t)));
    if (v < lo || v > hi) fail(fmt::format("{} is {}, outside [{}, {}]", what, v, lo, hi));
    return v;
  }
  double real(const std::string& what) {
    const std::string_view t = required_token(what);
    double v = 0;
    const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || p != t.data() + t.size())
      fail(fmt::format("expected {} (a number), found '{}'", what, printable(t)));
    if (!std::isfinite(v)) fail(fmt::format("{} is not a finite number: '{}'", what, printable(t)));
    return v;
  }
  /// The rest of the current line must be blank; consumes its newline (binary data follows).
  void end_line() {
    while (pos_ < b_.size() && (b_[pos_] == ' ' || b_[pos_] == '\t' || b_[pos_] == '\r')) ++pos_;
    if (pos_ < b_.size() && b_[pos_] == '\n') {
      ++pos_;
      ++line_;
    } else if (pos_ < b_.size()) {
      fail(fmt::format("unexpected '{}' at the end of the line", printable(b_.substr(pos_, 20))));
    }
  }
  void expect(std::string_view word, const std::string& more = "") {
    skip_space();  // the end markers follow text or the end of binary data
    const int at = line_;
    const std::string_view t = token();
    if (t != word)
      fail(t.empty() ? fmt::format("the file ends where {} was expected", word)
                     : fmt::format("expected {}{}, found '{}'{}", word, more.empty() ? "" : " " + more, printable(t),
                                   more.empty() ? "" : ": the section holds more than its count says (correct the count)"),
           lines_known_ ? at : 0);
  }
  /// Before item `i` (0-based) of the `n` `items` a count on line `count_line` announced (ASCII):
  /// an end marker there means the list is shorter than the count.
  void before_item(long i, long n, const char* items, int count_line) {
    if (f_.binary) return;
    skip_space();
    if (pos_ >= b_.size() || b_[pos_] != '$') return;
    const int at = line_;
    const std::size_t end = std::min(b_.find_first_of(" \t\r\n", pos_), b_.size());
    fail(fmt::format("found '{}' after {} of the {} {} announced on line {}: the section holds fewer than its count "
                     "says (correct the count to {}, or add the missing {})",
                     printable(b_.substr(pos_, end - pos_)), i, n, items, count_line, i, items),
         lines_known_ ? at : 0);
  }
  /// "after the N <items> announced on line L" for expect().
  static std::string after(long n, const char* items, int count_line) {
    return fmt::format("after the {} {} announced on line {}", n, items, count_line);
  }
  std::string quoted(const std::string& what) {
    skip_space();
    if (pos_ >= b_.size() || b_[pos_] != '"') fail(fmt::format("expected {} in double quotes", what));
    const std::size_t end = b_.find_first_of("\"\n", pos_ + 1);
    if (end == std::string_view::npos || b_[end] != '"') fail(fmt::format("{} has no closing quote on its line", what));
    std::string s(b_.substr(pos_ + 1, end - pos_ - 1));
    pos_ = end + 1;
    return s;
  }

  // ---------------------------------------------------------------- binary values
  template <class T>
  T bin(const char* what) {
    if (b_.size() - pos_ < sizeof(T)) fail(fmt::format("the file ends inside the binary data ({})", what));
    T v;
    std::memcpy(&v, b_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    lines_known_ = false;
    return v;
  }
  long bin_int(const char* what, long lo, long hi) {
    const long v = bin<std::int32_t>(what);
    if (v < lo || v > hi) fail(fmt::format("{} is {}, outside [{}, {}]", what, v, lo, hi));
    return v;
  }
  long bin_size(const char* what, long hi) {
    const std::uint64_t v = bin<std::uint64_t>(what);
    if (v > static_cast<std::uint64_t>(hi)) fail(fmt::format("{} is {}, more than {}", what, v, hi));
    return static_cast<long>(v);
  }
  double bin_real(const char* what) {
    const double v = bin<double>(what);
    if (!std::isfinite(v)) fail(fmt::format("{} is not a finite number", what));
    return v;
  }
  /// Integer or binary count / tag, as the file's mode says.
  long count(const char* what, long hi) { return f_.binary && v4() ? bin_size(what, hi) : integer(what, 0, hi); }
  long tag4(const char* what) { return f_.binary ? bin_size(what, LONG_MAX) : integer(what, LONG_MIN, LONG_MAX); }
  long int4(const char* what, long lo, long hi) { return f_.binary ? bin_int(what, lo, hi) : integer(what, lo, hi); }
  double real4(const char* what) { return f_.binary ? bin_real(what) : real(what); }

  /// Refuses `n` items of at least `bytes_each` bytes each that cannot fit in what is left of the file.
  void fits(long n, std::size_t bytes_each, const std::string& what) {
    const std::size_t left = b_.size() - pos_;
    if (n > 0 && static_cast<std::size_t>(n) > left / bytes_each)
      fail(fmt::format("the file announces {} {}, but only {} bytes are left in it: it is cut short, or the count is wrong",
                       n, what, left));
  }

  // ---------------------------------------------------------------- sections
  void header() {
    const std::string_view first = b_.substr(0, std::min<std::size_t>(b_.size(), 11));
    if (first != "$MeshFormat") {
      // Say what the file looks like, and what to do about it.
      std::string hint;
      const std::size_t text = b_.find_first_not_of(" \t\r\n");
      if (b_.substr(0, 3) == "\xEF\xBB\xBF")
        hint = "; it starts with a UTF-8 byte-order mark: save it without one";
      else if (text != std::string_view::npos && text > 0 && b_.substr(text, 11) == "$MeshFormat")
        hint = "; remove the blank space before $MeshFormat";
      else if (b_.substr(0, 5) == "solid" || (b_.size() >= 84 && b_.size() == 84 + 50 * static_cast<std::size_t>(
                                                                   static_cast<unsigned char>(b_[80]) |
                                                                   static_cast<unsigned char>(b_[81]) << 8 |
                                                                   static_cast<unsigned char>(b_[82]) << 16 |
                                                                   static_cast<std::size_t>(static_cast<unsigned char>(b_[83])) << 24)))
        hint = "; it looks like an STL surface: write a .geo with Merge \"FILE.stl\"; Physical Surface(\"wall\") = "
               "{1}; and turn it into a .msh with tunica mesh FILE.geo -o FILE.msh";
      else
        hint = "; a Gmsh script must be named .geo, and is meshed only with --allow-scripts";
      fail(fmt::format("not a Gmsh mesh: a .msh file must begin with $MeshFormat, this one begins with '{}'{}",
                       printable(b_.substr(0, 20)), hint),
           1);
    }
    section_ = "$MeshFormat";
    section_line_ = 1;
    token();
    skip_space();
    const int at = line_;
    const std::string_view vt = required_token("the format version");
    if (vt == "4.1") f_.version = 4.1;
    else if (vt == "2.2" || vt == "2.1" || vt == "2" || vt == "2.0") f_.version = 2.2;
    else
      fail(fmt::format("Gmsh mesh format version '{}' is not read; save the mesh as version 4.1 or 2.2 "
                       "(Gmsh: Mesh.MshFileVersion = 4.1)",
                       printable(vt)),
           at);
    f_.binary = integer("the file type (0 ASCII, 1 binary)", 0, 1) == 1;
    const long size = integer("the data size", 1, 64);
    if (size != 8) fail(fmt::format("data size {} is not read (Gmsh writes 8)", size));
    if (f_.binary) {
      end_line();
      const std::int32_t one = bin<std::int32_t>("the byte-order mark");
      if (one != 1)
        fail("the binary file was written with another byte order (big-endian) than this machine's; save it as ASCII");
    }
    expect("$EndMeshFormat");
    section_.clear();
  }

  void skip_section(const std::string& name) {
    const std::string end = "$End" + name;
    std::size_t at = pos_;
    for (;;) {
      at = b_.find(end, at);
      if (at == std::string_view::npos)
        fail(fmt::format("section {} is not closed by $End{}", section_, printable(name)));
      // A whole token: at the start of a line (or after white space) and followed by white space or the end.
      const bool starts = at == 0 || is_space(b_[at - 1]);
      const bool ends = at + end.size() == b_.size() || is_space(b_[at + end.size()]);
      if (starts && ends) break;
      at += end.size();
    }
    if (lines_known_) line_ += static_cast<int>(std::count(b_.begin() + pos_, b_.begin() + at, '\n'));
    pos_ = at + end.size();
  }

  void physical_names() {
    const long n = integer("the number of physical names", 0, 1'000'000);
    fits(n, 6, "physical names");
    for (long i = 0; i < n; ++i) {
      skip_space();
      const int at = line_;
      const int dim = static_cast<int>(integer("the dimension of a physical group", 0, 3));
      const int tag = static_cast<int>(integer("the tag of a physical group", INT_MIN, INT_MAX));
      std::string name = quoted("the physical name");
      if (!f_.physical_names.emplace(std::make_pair(dim, tag), std::move(name)).second)
        fail(fmt::format("physical group {} of dimension {} is named twice", tag, dim), at);
    }
    expect("$EndPhysicalNames");
  }

  void entities() {
    if (f_.binary) end_line();
    long n[4];
    for (int d = 0; d < 4; ++d) n[d] = count("the number of entities", 10'000'000);
    for (int d = 0; d < 4; ++d) {
      fits(n[d], f_.binary ? 4 + 8 * (d == 0 ? 3 : 6) + 8 : 10, "entities");
      for (long i = 0; i < n[d]; ++i) {
        skip_space_ascii();
        const int at = line_;
        const int tag = static_cast<int>(int4("an entity tag", INT_MIN, INT_MAX));
        for (int k = 0; k < (d == 0 ? 3 : 6); ++k) real4("an entity's bounding coordinate");
        const long np = count("the number of physical tags", 100'000);
        fits(np, f_.binary ? 4 : 2, "physical tags");
        std::vector<int> phys;
        // Gmsh writes −t for an entity that belongs to physical group t with its orientation reversed
        // (`Physical Curve("x0") = {-5};`, or the signed tags an Extrude returns): the group is t.
        for (long k = 0; k < np; ++k)
          phys.push_back(std::abs(static_cast<int>(int4("a physical tag", -INT_MAX, INT_MAX))));
        if (d > 0) {
          const long nb = count("the number of bounding entities", 10'000'000);
          fits(nb, f_.binary ? 4 : 2, "bounding entities");
          for (long k = 0; k < nb; ++k) int4("a bounding entity tag", INT_MIN, INT_MAX);
        }
        if (f_.entity_physicals.count({d, tag}))
          fail(fmt::format("entity {} of dimension {} is defined twice", tag, d), lines_known_ ? at : 0);
        f_.entity_physicals[{d, tag}] = std::move(phys);
      }
    }
    expect("$EndEntities");
  }

  void reserve_nodes(long n) {
    if (n > kMaxMshNodes) fail(fmt::format("the file announces {} nodes; at most {} are allowed", n, kMaxMshNodes));
    fits(n, f_.binary ? (v4() ? 32 : 28) : 8, "nodes");
    f_.nodes.reserve(static_cast<std::size_t>(n));
  }
  void reserve_elements(long n) {
    if (n > kMaxMshElements)
      fail(fmt::format("the file announces {} elements; at most {} are allowed", n, kMaxMshElements));
    fits(n, f_.binary ? 12 : 4, "elements");
    f_.elements.reserve(static_cast<std::size_t>(n));
  }
  MshElementType element_type(long type, int line) {
    const MshElementType t = msh_element_type(static_cast<int>(type));
    if (t.dim < 0) fail(fmt::format("element type {} is not a Gmsh element type Tunica knows", type), line);
    return t;
  }
  void push_node(long tag, int at) {
    if (tag < 1) fail(fmt::format("node tag {} is not positive", tag), lines_known_ ? at : 0);
    MshFile::Node nd;
    nd.tag = tag;
    nd.line = lines_known_ ? at : 0;
    f_.nodes.push_back(nd);
  }

  void nodes4() {
    if (f_.binary) end_line();
    const long blocks = count("the number of node blocks", kMaxMshNodes);
    const long total = count("the number of nodes", LONG_MAX);
    reserve_nodes(total);
    tag4("the least node tag");
    tag4("the largest node tag");
    fits(blocks, f_.binary ? 20 : 8, "node blocks");
    for (long b = 0; b < blocks; ++b) {
      skip_space_ascii();
      const int block_line = line_;
      const int dim = static_cast<int>(int4("the dimension of a node block's entity", 0, 3));
      const int entity = static_cast<int>(int4("the tag of a node block's entity", INT_MIN, INT_MAX));
      const bool parametric = int4("the parametric flag of a node block", 0, 1) == 1;
      const long n = count("the number of nodes in a block", kMaxMshNodes);
      if (static_cast<long>(f_.nodes.size()) + n > total)
        fail(fmt::format("node block {} holds more nodes than the {} the section announces", b + 1, total));
      const std::size_t first = f_.nodes.size();
      for (long i = 0; i < n; ++i) {
        before_item(i, n, "nodes of the block", block_line);
        skip_space_ascii();
        push_node(tag4("a node tag"), line_);
        f_.nodes.back().entity_dim = dim;
        f_.nodes.back().entity = entity;
      }
      const int extra = parametric ? dim : 0;
      for (long i = 0; i < n; ++i) {
        MshFile::Node& nd = f_.nodes[first + static_cast<std::size_t>(i)];
        before_item(i, n, "node coordinates of the block", block_line);
        if (!f_.binary) {
          skip_space();
          nd.line = lines_known_ ? line_ : 0;  // the line of its coordinates
        }
        for (int k = 0; k < 3; ++k) nd.x(k) = real4("a node coordinate");
        for (int k = 0; k < extra; ++k) real4("a parametric coordinate");
      }
    }
    if (static_cast<long>(f_.nodes.size()) != total)
      fail(fmt::format("the node blocks hold {} nodes, the section announces {}", f_.nodes.size(), total));
    expect("$EndNodes");
  }

  void nodes2() {
    skip_space();
    const int count_line = line_;
    const long n = integer("the number of nodes", 0, LONG_MAX);
    reserve_nodes(n);
    if (f_.binary) end_line();
    for (long i = 0; i < n; ++i) {
      before_item(i, n, "nodes", count_line);
      skip_space_ascii();
      const int at = line_;
      push_node(f_.binary ? bin_int("a node tag", INT_MIN, INT_MAX) : integer("a node tag", LONG_MIN, LONG_MAX), at);
      for (int k = 0; k < 3; ++k) f_.nodes.back().x(k) = f_.binary ? bin_real("a node coordinate") : real("a node coordinate");
    }
    expect("$EndNodes", f_.binary ? "" : after(n, "nodes", count_line));
  }
  void skip_space_ascii() {
    if (!f_.binary) skip_space();
  }

  void push_element(long tag, int type, int dim, int entity, int physical, int at) {
    if (tag < 1) fail(fmt::format("element tag {} is not positive", tag), lines_known_ ? at : 0);
    MshFile::Element e;
    e.tag = tag;
    e.type = type;
    e.entity_dim = dim;
    e.entity = entity;
    e.physical = physical;
    e.line = lines_known_ ? at : 0;
    e.first = static_cast<std::uint32_t>(f_.element_nodes.size());
    f_.elements.push_back(e);
  }
  void node_tag_of_element(long v) {
    if (v < 1) fail(fmt::format("element {} names node tag {}, which is not positive", f_.elements.back().tag, v));
    f_.element_nodes.push_back(v);
  }
  void check_node_room(long more) {
    if (static_cast<long>(f_.element_nodes.size()) + more > 8 * kMaxMshElements)
      fail("the elements name more nodes than Tunica reads in one file");
  }

  void elements4() {
    if (f_.binary) end_line();
    const long blocks = count("the number of element blocks", kMaxMshElements);
    const long total = count("the number of elements", LONG_MAX);
    reserve_elements(total);
    tag4("the least element tag");
    tag4("the largest element tag");
    fits(blocks, f_.binary ? 20 : 8, "element blocks");
    for (long b = 0; b < blocks; ++b) {
      skip_space_ascii();
      const int at_block = line_;
      const int dim = static_cast<int>(int4("the dimension of an element block's entity", 0, 3));
      const int entity = static_cast<int>(int4("the tag of an element block's entity", INT_MIN, INT_MAX));
      const long type = int4("an element type", INT_MIN, INT_MAX);
      const MshElementType t = element_type(type, lines_known_ ? at_block : 0);
      const long n = count("the number of elements in a block", kMaxMshElements);
      if (static_cast<long>(f_.elements.size()) + n > total)
        fail(fmt::format("element block {} holds more elements than the {} the section announces", b + 1, total));
      fits(n, (f_.binary ? 8 : 2) * static_cast<std::size_t>(1 + t.nodes), "elements");
      check_node_room(n * t.nodes);
      for (long i = 0; i < n; ++i) {
        before_item(i, n, "elements of the block", at_block);
        skip_space_ascii();
        const int at = line_;
        push_element(tag4("an element tag"), static_cast<int>(type), dim, entity, 0, at);
        for (int k = 0; k < t.nodes; ++k) node_tag_of_element(tag4("a node tag of an element"));
      }
    }
    if (static_cast<long>(f_.elements.size()) != total)
      fail(fmt::format("the element blocks hold {} elements, the section announces {}", f_.elements.size(), total));
    expect("$EndElements");
  }

  void elements2() {
    skip_space();
    const int count_line = line_;
    const long n = integer("the number of elements", 0, LONG_MAX);
    reserve_elements(n);
    if (!f_.binary) {
      for (long i = 0; i < n; ++i) {
        before_item(i, n, "elements", count_line);
        skip_space();
        const int at = line_;
        const long tag = integer("an element tag", LONG_MIN, LONG_MAX);
        const long type = integer("an element type", INT_MIN, INT_MAX);
        const MshElementType t = element_type(type, at);
        const long ntags = integer("the number of element tags", 0, 64);
        long tags[64] = {};
        for (long k = 0; k < ntags; ++k) tags[k] = integer("an element tag (physical, elementary, ...)", INT_MIN, INT_MAX);
        check_node_room(t.nodes);
        push_element(tag, static_cast<int>(type), t.dim, ntags > 1 ? static_cast<int>(tags[1]) : 0,
                     ntags > 0 ? static_cast<int>(tags[0]) : 0, at);
        for (int k = 0; k < t.nodes; ++k) node_tag_of_element(integer("a node tag of an element", LONG_MIN, LONG_MAX));
      }
    } else {
      end_line();
      long read = 0;
      while (read < n) {
        const long type = bin_int("an element type", INT_MIN, INT_MAX);
        const MshElementType t = element_type(type, 0);
        const long count_in = bin_int("the number of elements that follow", 1, n - read);
        const long ntags = bin_int("the number of element tags", 0, 64);
        fits(count_in, 4 * static_cast<std::size_t>(1 + ntags + t.nodes), "elements");
        check_node_room(count_in * t.nodes);
        for (long i = 0; i < count_in; ++i) {
          const long tag = bin_int("an element tag", INT_MIN, INT_MAX);
          long tags[64] = {};
          for (long k = 0; k < ntags; ++k) tags[k] = bin_int("an element tag (physical, elementary, ...)", INT_MIN, INT_MAX);
          push_element(tag, static_cast<int>(type), t.dim, ntags > 1 ? static_cast<int>(tags[1]) : 0,
                       ntags > 0 ? static_cast<int>(tags[0]) : 0, 0);
          for (int k = 0; k < t.nodes; ++k) node_tag_of_element(bin_int("a node tag of an element", INT_MIN, INT_MAX));
        }
        read += count_in;
      }
    }
    expect("$EndElements", f_.binary ? "" : after(n, "elements", count_line));
  }

  void element_data() {
    MshFile::ElementData d;
    d.line = section_line_known_ ? section_line_ : 0;
    const long nstr = integer("the number of string tags", 0, 100);
    for (long i = 0; i < nstr; ++i) {
      std::string s = quoted("a string tag");
      if (i == 0) d.name = std::move(s);
    }
    const long nreal = integer("the number of real tags", 0, 100);
    for (long i = 0; i < nreal; ++i) real("a real tag");
    const long nint = integer("the number of integer tags", 3, 100);
    long ints[3] = {};
    for (long i = 0; i < nint; ++i) {
      const long v = integer("an integer tag", LONG_MIN, LONG_MAX);
      if (i < 3) ints[i] = v;
    }
    const long components = ints[1], n = ints[2];
    if (components < 1 || components > 9) fail(fmt::format("element data with {} components per element", components));
    if (n < 0 || n > kMaxMshElements) fail(fmt::format("element data for {} elements", n));
    d.components = static_cast<int>(components);
    if (f_.binary) end_line();
    fits(n, (f_.binary ? 4 + 8 * static_cast<std::size_t>(components) : 2 * (1 + static_cast<std::size_t>(components))),
         "element data values");
    d.tags.reserve(static_cast<std::size_t>(n));
    d.values.reserve(static_cast<std::size_t>(n * components));
    for (long i = 0; i < n; ++i) {
      // Binary element tags are 4-byte int here in 4.1 as in 2.2 (as Gmsh 4.8 writes them).
      d.tags.push_back(f_.binary ? bin_int("an element tag", INT_MIN, INT_MAX) : integer("an element tag", LONG_MIN, LONG_MAX));
      for (long k = 0; k < components; ++k)
        d.values.push_back(f_.binary ? bin<double>("an element-data value") : real("an element-data value"));
    }
    expect("$EndElementData");
    f_.element_data.push_back(std::move(d));
  }

  std::string_view b_;
  const std::string& path_;
  std::size_t pos_ = 0;
  int line_ = 1;
  bool lines_known_ = true;
  bool section_line_known_ = true;  ///< lines are reported at all
  std::string section_;
  int section_line_ = 0;
  MshFile f_;
};

}  // namespace

MshFile parse_msh(std::string_view bytes, const std::string& path, bool lines) {
  return Parser(bytes, path, lines).parse();
}

}  // namespace tunica
