#include "core/scene/drive.h"

#include <cmath>

#include "core/scene/scene_desc.h"

namespace f2 {

namespace {
/// A value a scene number can take: finite, within the float range.
bool usable(double v) { return std::fabs(v) <= 3.4028234663852886e38; }

constexpr std::array<std::string_view, kDriveChannelCount> kNames = {
    "px", "py", "pz", "rx", "ry", "rz", "intensity", "d", "r", "g", "b"};
}  // namespace

std::string_view driveChannelName(DriveChannel channel) { return kNames[std::size_t(channel)]; }

std::optional<DriveChannel> driveChannelFromWord(std::string_view word) {
    for (std::size_t i = 0; i < kNames.size(); ++i) {
        if (kNames[i] == word) return DriveChannel(i);
    }
    return std::nullopt;
}

std::array<std::string_view, kDriveChannelCount> driveChannelNames() { return kNames; }

int driveSlot(DriveChannel channel) {
    switch (channel) {
        case DriveChannel::Intensity:
        case DriveChannel::D:
        case DriveChannel::R:
            return 0;
        case DriveChannel::G:
            return 1;
        case DriveChannel::B:
            return 2;
        default:
            return int(channel);  // px … rz
    }
}

std::string Drive::place() const { return file + ":" + std::to_string(line) + ":" + std::to_string(column); }

void applyDrives(const TrackDrives& drives, double t, Pose& pose) {
    for (int slot = 0; slot < 6; ++slot) {
        const Drive* drive = drives.bySlot[std::size_t(slot)].get();
        if (!drive) continue;
        const double v = drive->valueAt(t);
        if (!usable(v)) continue;
        float& number = slot < 3 ? pose.position[slot] : pose.rotation[slot - 3];
        number = float(v);
    }
}

std::optional<std::string> firstDriveProblem(const SceneDesc& scene, double t) {
    for (const std::shared_ptr<const Drive>& drive : scene.drives) {
        ExpressionFailure failure;
        const double v = drive->valueAt(t, &failure);
        if (usable(v)) continue;
        // Past the float range a scene number would be infinite too.
        const std::string why = std::isfinite(v) ? "beyond the largest number (3.4e38)" : failure.message;
        return drive->place() + ": error: at frame " + shortestDecimal(t) + ", '/drive " + drive->target +
               " " + std::string(driveChannelName(drive->channel)) + " " + drive->expression +
               "' has no finite value: " + why;
    }
    return std::nullopt;
}

std::optional<std::string> firstDriveProblem(const SceneDesc& scene, std::span<const double> times) {
    if (scene.drives.empty()) return std::nullopt;
    for (double t : times) {
        if (std::optional<std::string> problem = firstDriveProblem(scene, t)) return problem;
    }
    return std::nullopt;
}

}  // namespace f2
