#pragma once
// A subdivision control cage as plain data: what an OBJ file (or any other
// front-end) says, before OpenSubdiv has seen it. Indices are 0-based.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <string>
#include <vector>

namespace facet::scene {

// The Sdc options a cage can carry, spelled as OpenSubdiv's OBJ tags do.
enum class BoundaryInterpolation { None, EdgeOnly, EdgeAndCorner };
enum class FaceVaryingInterpolation { Smooth, CornersOnly, CornersPlus1, CornersPlus2, Boundaries, All };
enum class CreasingMethod { Uniform, Chaikin };
enum class TriangleSubdivision { Catmark, Smooth };

struct SubdivisionOptions {
  BoundaryInterpolation boundary = BoundaryInterpolation::EdgeOnly;  // OpenSubdiv shapes' default
  FaceVaryingInterpolation faceVarying = FaceVaryingInterpolation::All;
  CreasingMethod creasing = CreasingMethod::Uniform;
  TriangleSubdivision triangles = TriangleSubdivision::Catmark;
};

struct CreaseEdge {
  int v0 = 0;
  int v1 = 0;
  float sharpness = 0.0f;  // >= 10 is infinitely sharp for OpenSubdiv
};

struct CornerVertex {
  int vertex = 0;
  float sharpness = 0.0f;
};

struct ControlCage {
  std::string source;  // file name or label, used in error messages
  std::vector<glm::dvec3> positions;
  std::vector<int> faceVertexCounts;
  std::vector<int> faceVertexIndices;  // concatenated, counter-clockwise seen from outside
  // Optional, one per faceVertexIndices entry: the authored shading normals
  // of a mesh rendered as authored (ignored when it is subdivided).
  std::vector<glm::dvec3> faceVertexNormals;
  // Optional where it has authored normals, likewise one per corner: the
  // mesh's tangents (glTF TANGENT, or MikkTSpace's), xyz along dP/du and w
  // the sign that makes w (n x xyz) the bitangent pointing up the image.
  std::vector<glm::dvec4> faceVertexTangents;
  // Optional texture coordinates, one face-varying channel as OpenSubdiv
  // takes it: the distinct values, and one index into them per
  // faceVertexIndices entry. Corners that share a vertex but not a value
  // form a seam; options.faceVarying says how the values are subdivided.
  std::vector<glm::dvec2> texcoords;
  std::vector<int> faceVertexTexcoords;
  // Optional, likewise: a second set of texture coordinates (glTF
  // TEXCOORD_1) and linear RGB vertex colours (glTF COLOR_0).
  std::vector<glm::dvec2> texcoords1;
  std::vector<int> faceVertexTexcoords1;
  std::vector<glm::dvec3> colors;
  std::vector<int> faceVertexColors;
  std::vector<CreaseEdge> creases;
  std::vector<CornerVertex> corners;
  std::vector<int> holes;  // face indices
  SubdivisionOptions options;

  int faceCount() const { return static_cast<int>(faceVertexCounts.size()); }
  int vertexCount() const { return static_cast<int>(positions.size()); }
};

}  // namespace facet::scene
