// The vcglib mesh type of the command-line tool: what the importers fill and the exporters write.
#pragma once
#include <vcg/complex/complex.h>

namespace lowstretch {

class ToolVertex;
class ToolFace;
struct ToolUsedTypes : public vcg::UsedTypes<vcg::Use<ToolVertex>::AsVertexType, vcg::Use<ToolFace>::AsFaceType> {};
class ToolVertex : public vcg::Vertex<ToolUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d, vcg::vertex::TexCoord2f,
                                      vcg::vertex::Qualityd, vcg::vertex::Color4b, vcg::vertex::BitFlags> {};
class ToolFace : public vcg::Face<ToolUsedTypes, vcg::face::VertexRef, vcg::face::Normal3d, vcg::face::WedgeTexCoord2f,
                                  vcg::face::Qualityd, vcg::face::Color4b, vcg::face::BitFlags> {};
class ToolMesh : public vcg::tri::TriMesh<std::vector<ToolVertex>, std::vector<ToolFace>> {};

}  // namespace lowstretch
