/// @file cbd_pipeline.cpp
/// Placeholder for the algorithm stages: the layout (common base domain) and the
/// cross-parameterization do not exist yet in cbd_core. Replace the body of `runPipeline`.

#include "cbd_pipeline.h"

namespace cbdplugin {

cbd::Status runPipeline(const PipelineRequest& request, vcg::CallBackPos* /*cb*/) {
  const std::string text =
      "cbd: " + request.filterName + " needs the layout stage, which this build does not have yet";
  return cbd::Status::error(cbd::ErrorCode::LayoutFailed, text);
}

}  // namespace cbdplugin
