#include "io/fields/xdmf_text.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace ccm::fields {
namespace {

// Escapes the five XML special characters of free text.
std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

struct Item {
  std::string dataset;
  long rows;
  int cols;
  bool is_int;
};

std::string data_item(const XdmfLayout& l, const Item& item, const char* indent) {
  const std::string dims =
      item.cols == 1 ? fmt::format("{}", item.rows) : fmt::format("{} {}", item.rows, item.cols);
  return fmt::format(
      "{}<DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"{}\" "
      "Format=\"HDF\">{}:{}</DataItem>\n",
      indent, dims, item.is_int ? "Int" : "Float", item.is_int ? 4 : 8, xml_escaped(l.h5_name),
      item.dataset);
}

std::string attribute(const XdmfLayout& l, const FieldInfo& info, const std::string& center,
                      const Item& item) {
  return fmt::format(
             "          <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"{}\">\n"
             "            <Information Name=\"unit\" Value=\"{}\"/>\n"
             "            <Information Name=\"meaning\" Value=\"{}\"/>\n",
             info.name, info.components == 3 ? "Vector" : "Scalar", center, info.unit,
             xml_escaped(std::string(info.meaning))) +
         data_item(l, item, "            ") + "          </Attribute>\n";
}

std::string bodies_grid(const XdmfLayout& l, int frame) {
  std::string s = fmt::format(
      "        <Grid Name=\"bodies\" GridType=\"Uniform\">\n"
      "          <Topology TopologyType=\"Tetrahedron\" NumberOfElements=\"{}\">\n",
      l.n_tets);
  s += data_item(l, {kTetsDataset, l.n_tets, 4, true}, "            ");
  s += "          </Topology>\n          <Geometry GeometryType=\"XYZ\">\n";
  s += data_item(l, {kNodesDataset, l.n_nodes, 3, false}, "            ");
  s += "          </Geometry>\n";
  for (FieldKind kind : l.fields) {
    const FieldInfo& info = field_info(kind);
    if (info.centre == FieldCentre::face) continue;
    const bool node = info.centre == FieldCentre::node;
    const Item item =
        kind == FieldKind::body_id
            ? Item{kBodyIdDataset, l.n_tets, 1, true}
            : Item{frame_dataset(frame, kind), node ? l.n_nodes : l.n_tets, info.components, false};
    s += attribute(l, info, node ? "Node" : "Cell", item);
  }
  return s + "        </Grid>\n";
}

std::string surfaces_grid(const XdmfLayout& l, int frame) {
  std::string s = fmt::format(
      "        <Grid Name=\"surfaces\" GridType=\"Uniform\">\n"
      "          <Topology TopologyType=\"Triangle\" NumberOfElements=\"{}\">\n",
      l.n_faces);
  s += data_item(l, {kFacesDataset, l.n_faces, 3, true}, "            ");
  s += "          </Topology>\n          <Geometry GeometryType=\"XYZ\">\n";
  s += data_item(l, {kNodesDataset, l.n_nodes, 3, false}, "            ");
  s += "          </Geometry>\n";
  for (FieldKind kind : l.fields) {
    const FieldInfo& info = field_info(kind);
    // The node fields again (the same datasets): the surfaces can be warped and coloured alone.
    if (info.centre == FieldCentre::node)
      s += attribute(l, info, "Node", {frame_dataset(frame, kind), l.n_nodes, 3, false});
    else if (kind == FieldKind::contact_pressure)
      s += attribute(l, info, "Cell", {frame_dataset(frame, kind), l.n_faces, 1, false});
    else if (kind == FieldKind::body_id)
      s += attribute(l, info, "Cell", {kFaceBodyIdDataset, l.n_faces, 1, true});
  }
  return s + "        </Grid>\n";
}

}  // namespace

std::string frame_dataset(int frame, FieldKind kind) {
  return fmt::format("/frames/{:06d}/{}", frame, field_info(kind).name);
}

bool has_surface_grid(const std::vector<FieldKind>& fields) {
  return std::find(fields.begin(), fields.end(), FieldKind::contact_pressure) != fields.end();
}

std::string xdmf_text(const XdmfLayout& l) {
  std::string s =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<!-- ccm field output (docs/fields.md): SI units, time in s -->\n"
      "<Xdmf xmlns:xi=\"http://www.w3.org/2001/XInclude\" Version=\"3.0\">\n"
      "  <Domain>\n";
  s += fmt::format("    <Information Name=\"title\" Value=\"{}\"/>\n", xml_escaped(l.title));
  s += "    <Grid Name=\"ccm\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  const bool surfaces = has_surface_grid(l.fields) && l.n_faces > 0;
  for (size_t k = 0; k < l.times.size(); ++k) {
    const int frame = static_cast<int>(k);
    s += fmt::format(
        "      <Grid Name=\"frame {}\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
        "        <Time Value=\"{:.17g}\"/>\n",
        frame, l.times[k]);
    s += bodies_grid(l, frame);
    if (surfaces) s += surfaces_grid(l, frame);
    s += "      </Grid>\n";
  }
  return s + "    </Grid>\n  </Domain>\n</Xdmf>\n";
}

}  // namespace ccm::fields
