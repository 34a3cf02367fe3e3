#pragma once
/// `/drive <target> <channel> (<expression>)` (SPEC 10.7): one channel of a
/// target computed every frame from `frame` and `time`, replacing that
/// channel's keyed value. A drive lives in the track of the property it
/// drives (Track::drives), so that every evaluation of a track
/// (anim/track.h's evaluateTrack) applies it; the scene also lists them all
/// (SceneDesc::drives) for the checks, `f2 info` and the language server.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "core/math/expression_code.h"

namespace f2 {

struct Pose;
struct SceneDesc;

/// SPEC 10.7's channels, in the order messages list them.
enum class DriveChannel : std::uint8_t { Px, Py, Pz, Rx, Ry, Rz, Intensity, D, R, G, B };
inline constexpr int kDriveChannelCount = 11;

/// "px", …, "b".
std::string_view driveChannelName(DriveChannel channel);
/// The channel named `word`, if any.
std::optional<DriveChannel> driveChannelFromWord(std::string_view word);
/// Every channel's name, in order.
std::array<std::string_view, kDriveChannelCount> driveChannelNames();
/// Which of a track's six numbers the channel is: a pose's px … rz are 0 … 5;
/// a property track keeps r g b in 0 1 2 and its one value (intensity, d) in 0.
int driveSlot(DriveChannel channel);

/// The names a drive's expression may read besides the scene's variables
/// (SPEC 10.7): the frame being drawn, and the time in seconds.
inline constexpr std::array<std::string_view, 2> kDriveInputs = {"frame", "time"};

struct Drive {
    std::string target;  ///< as written after `{ … }`: "ball", "f2.head", "camera", "lamp"
    DriveChannel channel = DriveChannel::Px;
    std::string expression;  ///< the `( … )` as written
    std::string file;        ///< where the `/drive` stands, for the errors of a frame
    int line = 0, column = 0;
    ExpressionCode code;
    int fps = 24;  ///< the scene's, for `time`

    /// The value at frame t (frames, may be fractional), or NaN and, when
    /// `failure` is given, why.
    double valueAt(double frame, ExpressionFailure* failure = nullptr) const {
        const std::array<double, 2> inputs = {frame, frame / double(fps)};
        return code.evaluate(inputs, failure);
    }
    /// "FILE:LINE:COL".
    std::string place() const;
};

/// The drives of one track, by slot (driveSlot).
struct TrackDrives {
    std::array<std::shared_ptr<const Drive>, 6> bySlot{};
};

/// `pose` with its driven numbers replaced by the drives' values at frame t.
/// A value that is not finite leaves the number as it was: the frame is an
/// error of the render (firstDriveProblem), never a NaN in the picture.
void applyDrives(const TrackDrives& drives, double t, Pose& pose);

/// The error of frame t if a drive of the scene has no finite value there:
/// "FILE:LINE:COL: error: at frame 12, '/drive ball px (…)' has no finite
/// value: division by zero". Nothing when every drive has one.
std::optional<std::string> firstDriveProblem(const SceneDesc& scene, double t);

/// The same for each of `times` (a motion-blurred frame's sub-frames).
std::optional<std::string> firstDriveProblem(const SceneDesc& scene, std::span<const double> times);

}  // namespace f2
