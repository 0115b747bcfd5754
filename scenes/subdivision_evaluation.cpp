// The limit surface and its face-varying channels evaluated on a patch at face
// parameters, through OpenSubdiv's patch basis.
#include "scenes/subdivision_internal.h"

namespace facet::scene {
namespace {

// Sum_k w[k] points[cvs[k]], k < count, with derivatives in face parameters.
LimitPoint combine(const PatchInfo& info, const BezierPatch& bezier, const double* wP, const double* wDu,
                   const double* wDv, Far::ConstIndexArray cvs, int count, const std::vector<detail::OsdPoint>& points,
                   double u, double v) {
  LimitPoint result;
  for (int k = 0; k < count; ++k) {
    const glm::dvec3& p = points[std::size_t(cvs[k])].p;
    result.position += wP[k] * p;
    result.du += wDu[k] * p;
    result.dv += wDv[k] * p;
  }
  // OpenSubdiv scales derivatives by 2^depth, also on the sub-faces of
  // non-quad faces, which start at depth 1 and so span 2^-(depth-1) of
  // their ptex face: there its derivatives are twice ours (the
  // finite-difference test holds this). Rescale to ptex face parameters.
  const double derivativeScale = 1.0 / (info.domain.size * static_cast<double>(1 << info.depth));
  result.du *= derivativeScale;
  result.dv *= derivativeScale;
  if (bezier.gregory) {
    // OpenSubdiv's Gregory derivatives freeze the rational interior
    // (see the header); differentiate the same patch exactly instead.
    const PatchDomain& domain = info.domain;
    BezierSample exact = evaluateBezierPatch(bezier, (u - domain.u0) / domain.size, (v - domain.v0) / domain.size);
    result.du = exact.du / domain.size;
    result.dv = exact.dv / domain.size;
  }
  return result;
}

}  // namespace

LimitPoint SubdivisionSurface::evaluatePatch(int index, double u, double v) const {
  const Far::PatchTable::PatchHandle& handle = impl_->handles.at(std::size_t(index));
  double wP[20], wDu[20], wDv[20];
  impl_->patchTable->EvaluateBasis(handle, u, v, wP, wDu, wDv);
  const Far::ConstIndexArray cvs = impl_->patchTable->GetPatchVertices(handle);
  return combine(impl_->patches[std::size_t(index)], impl_->bezierPatches[std::size_t(index)], wP, wDu, wDv, cvs,
                 cvs.size(), impl_->points, u, v);
}

LimitPoint SubdivisionSurface::evaluateChannel(Channel channel, int index, double u, double v) const {
  if (!hasChannel(channel)) return {};
  const Impl::FaceVarying& values = impl_->channels[std::size_t(channel)];
  const Far::PatchTable::PatchHandle& handle = impl_->handles.at(std::size_t(index));
  double wP[20], wDu[20], wDv[20];
  impl_->patchTable->EvaluateBasisFaceVarying(handle, u, v, wP, wDu, wDv, nullptr, nullptr, nullptr, values.fvar);
  const Far::PatchDescriptor::Type type = values.types[std::size_t(index)];
  return combine(impl_->patches[std::size_t(index)], values.patches[std::size_t(index)], wP, wDu, wDv,
                 impl_->patchTable->GetPatchFVarValues(handle, values.fvar),
                 Far::PatchDescriptor::GetNumControlVertices(type), values.points, u, v);
}

LimitTexcoord SubdivisionSurface::evaluateTexcoord(int index, double u, double v, int set) const {
  const LimitPoint sum = evaluateChannel(set == 1 ? Channel::Texcoord1 : Channel::Texcoord0, index, u, v);
  return {glm::dvec2(sum.position), glm::dvec2(sum.du), glm::dvec2(sum.dv)};
}

glm::dvec3 SubdivisionSurface::evaluateColor(int index, double u, double v) const {
  return hasChannel(Channel::Color) ? evaluateChannel(Channel::Color, index, u, v).position : glm::dvec3(1.0);
}

std::optional<int> SubdivisionSurface::findPatch(int ptexFace, double u, double v) const {
  const Far::PatchTable::PatchHandle* handle = impl_->patchMap->FindPatch(ptexFace, u, v);
  if (!handle) return std::nullopt;
  return handle->patchIndex;
}

std::optional<LimitPoint> SubdivisionSurface::evaluateFace(int ptexFace, double u, double v) const {
  std::optional<int> index = findPatch(ptexFace, u, v);
  if (!index) return std::nullopt;
  return evaluatePatch(*index, u, v);
}

}  // namespace facet::scene
