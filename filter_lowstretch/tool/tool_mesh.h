// The vcglib mesh type of the command-line tool: what the importers fill and the exporters write.
// No normals and no colours: nothing reads or writes them, and at 2M vertices they took 170 MB.
#pragma once
#include <vcg/complex/complex.h>

namespace lowstretch {

class ToolVertex;
class ToolFace;
struct ToolUsedTypes : public vcg::UsedTypes<vcg::Use<ToolVertex>::AsVertexType, vcg::Use<ToolFace>::AsFaceType> {};
class ToolVertex : public vcg::Vertex<ToolUsedTypes, vcg::vertex::Coord3d, vcg::vertex::TexCoord2f,
                                      vcg::vertex::Qualityd, vcg::vertex::BitFlags> {};
class ToolFace : public vcg::Face<ToolUsedTypes, vcg::face::VertexRef, vcg::face::WedgeTexCoord2f,
                                  vcg::face::Qualityd, vcg::face::BitFlags> {};
class ToolMesh : public vcg::tri::TriMesh<std::vector<ToolVertex>, std::vector<ToolFace>> {};

}  // namespace lowstretch
