#pragma once
/// The Embree peer (bench/embree_peer) run on one frame, for `f2 bench --study
/// --peer`: the frame is exported as a primitive list, the peer renders it once
/// per BVH update mode, and the best whole-frame rate is kept, as
/// scripts/compare_peers.sh does (docs/performance.md).
#include <optional>
#include <string>
#include <vector>

#include "core/render/camera.h"
#include "core/scene/scene_desc.h"

namespace f2::cli {

struct PeerSettings {
    std::string program;  ///< path of f2_embree_peer
    int threads = 2;
    double seconds = 1.0;  ///< timed per mode
    std::vector<std::string> modes = {"low", "medium", "high", "refit"};
};

struct PeerResult {
    double fps = 0;    ///< whole frame (render + BVH update), the best mode's
    std::string mode;  ///< that mode
};

/// Renders `scene` at time t through `camera` with the peer; nullopt with
/// `error` set when the frame cannot be written or the peer fails.
std::optional<PeerResult> runPeer(const PeerSettings& settings, const SceneDesc& scene, double t,
                                  const Camera& camera, const std::string& name, std::string& error);

}  // namespace f2::cli
