#include "core/method_types.h"

namespace lowstretch {

const char* to_string(BoundaryShape shape) {
  switch (shape) {
    case BoundaryShape::Square: return "square";
    case BoundaryShape::Circle: return "circle";
    case BoundaryShape::Natural: return "natural";
    case BoundaryShape::Given: return "given";
  }
  return "?";
}

const char* to_string(InitialWeights weights) {
  switch (weights) {
    case InitialWeights::Floater: return "floater";
    case InitialWeights::MeanValue: return "meanvalue";
    case InitialWeights::Harmonic: return "harmonic";
  }
  return "?";
}

const char* to_string(StopReason reason) {
  switch (reason) {
    case StopReason::StretchRose: return "L2 stretch stopped falling";
    case StopReason::MaxPasses: return "max passes reached";
  }
  return "?";
}

}  // namespace lowstretch
