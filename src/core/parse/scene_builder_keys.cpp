#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/parse/expression.h"
#include "core/parse/number.h"
#include "core/parse/quoted_text.h"
#include "core/parse/scene_builder.h"
#include "core/parse/suggest.h"
#include "core/parse/unusual_char.h"

namespace f2::parsing {

void SceneBuilder::parseAnim() {
    if (!expectCounts() || failed(0)) return;
    // Only validates: /key needs no /anim (SPEC 6).
    if (argCount() == 1) {
        target(0, CameraTarget::Accepted, LightTarget::Accepted);
        return;
    }
    if (arg(0) == kCameraName) {
        error(argPos(1), "the camera has no parts");
        return;
    }
    if (lightNamed(arg(0))) {
        error(argPos(1), "a light has no parts");
        return;
    }
    if (arg(0).find('.') != std::string_view::npos) {
        error(argPos(0), "'/anim' with two arguments takes a name and a part, got " + quoteToken(arg(0)));
        return;
    }
    if (const std::optional<std::size_t> object = existing(arg(0), arg(0), argPos(0))) {
        partOf(*object, arg(1), argPos(1));
    }
}

void SceneBuilder::parseInterp() {
    if (!expectCounts()) return;
    const std::optional<Target> t = target(0, CameraTarget::Accepted, LightTarget::Accepted);
    const std::optional<Easing> mode = easing(1, argCount());
    if (!t || !mode) return;
    std::optional<Pos>& before = t->camera       ? cameraInterp_
                                 : t->light >= 0 ? lightBook(*t).interp
                                                 : interps_[slotOf(*t)];
    if (before) {
        warning(argPos(0), "interpolation of " + quoteToken(targetName(*t)) +
                               " is given again; it replaces the one at " + posText(*before));
    }
    before = argPos(0);
    trackOf(*t).interpolation = *mode;  // the last /interp of a target wins
}

const std::string& SceneBuilder::modeWordList() {
    static const std::string list = [] {
        const std::span<const Interpolation> modes = interpolationModes();
        std::string words;
        for (std::size_t k = 0; k < modes.size(); ++k) {
            if (k > 0) words += k + 1 == modes.size() ? " or " : ", ";
            words += interpolationName(modes[k]);
        }
        return words;
    }();
    return list;
}

std::optional<Interpolation> SceneBuilder::interpolationMode(int i) {
    const std::optional<Interpolation> mode = modeFromWord(arg(i));
    if (!mode) {
        error(argPos(i), noteCharacters("unknown interpolation " + quoteToken(arg(i)) + " (expected " +
                                            modeWordList() + ")",
                                        arg(i), argPos(i)));
    }
    return mode;
}

void SceneBuilder::parseKey() {
    // Counted before anything else so that the limit holds for broken lines too.
    if (++keyLines_ > limits_.maxKeyLines) {
        error(commandPos(),
              "too many '/key' lines: at most " + std::to_string(limits_.maxKeyLines) + " allowed");
        return;
    }
    const int n = argCount();
    if (n < 2) {
        error(commandPos(),
              noteCharacters("'/key' takes 2 or 8 arguments (a time, a target and 0 or 6 numbers), got " +
                                 std::to_string(n),
                             commandLine(), commandPos()));
        return;
    }
    // A word after the target that is not a mode names a property (SPEC 10.3),
    // unless it stands alone there: then it is read as a (mistyped) mode.
    const bool keysProperty =
        n > 2 && isWordArgument(2) && !modeFromWord(arg(2)) && (n > 3 || findKeyProperty(arg(2)) != nullptr);
    const int firstNumber = keysProperty ? 3 : 2;
    // The key's mode (SPEC 9.3) is a last argument that is a word, or a
    // mode with numbers after it (`bezier x1 y1 x2 y2`, SPEC 10.4). Only a
    // line short enough to be a key has its tokens stored.
    constexpr int kMostKeyArgs = 13;  // time, target, six numbers, bezier and its four
    int modeAt = n;
    if (n <= kMostKeyArgs) {
        for (int i = firstNumber; i < n && modeAt == n; ++i) {
            if (!isWordArgument(i)) continue;
            const std::optional<Interpolation> mode = modeFromWord(arg(i));
            if (mode && modeNumberCount(*mode) > 0) modeAt = i;
        }
        if (modeAt == n && n > firstNumber && isWordArgument(n - 1)) modeAt = n - 1;
    }
    const int numbers = modeAt - firstNumber;
    if (keysProperty) return parsePropertyKey(numbers, modeAt);
    if (numbers != 0 && numbers != 6) {
        error(commandPos(),
              noteCharacters("'/key' takes 0 or 6 numbers after the target, got " + std::to_string(numbers),
                             commandLine(), commandPos()));
        return;
    }
    bool ok = true;
    const KeyTime time = keyTime(0, ok);
    const std::optional<Target> t = target(1, CameraTarget::Accepted, LightTarget::Accepted);
    Pose p;
    if (numbers == 6) p = pose(2, true, ok);
    std::optional<Easing> mode;
    if (modeAt < n) {
        mode = easing(modeAt, n);
        ok = ok && mode.has_value();
    }
    if (!t || !ok) return;
    if (t->light >= 0 && lightMotion(*t).ambient) {
        error(argPos(1), quoteToken(arg(1)) +
                             " is an ambient light: it has no pose (key its intensity: "
                             "'/key <t> " +
                             std::string(arg(1)) + " intensity <i>')");
        return;
    }
    if (t->camera) {
        // `/camera` may come later: its pose is filled in at the end.
        cameraKeys_.push_back({time, numbers == 6 ? std::optional<Pose>(p) : std::nullopt, mode, argPos(0)});
        return;
    }
    // Without numbers: an object's pose as created, a part's zero offset
    // and rotation, a light's identity.
    if (numbers == 0 && t->part < 0 && t->light < 0) p = scene_.objects[t->object].rest;
    addKey(*t, std::nullopt, time, {time.value, p, mode}, argPos(0));
}

void SceneBuilder::parsePropertyKey(int numbers, int modeAt) {
    const KeyPropertySpec* spec = findKeyProperty(arg(2));
    if (!spec) {
        std::string expected = "expected six numbers, a mode, or a property:";
        for (const KeyPropertySpec& p : keyProperties()) expected += " " + std::string(p.word);
        ClosestWord closest(arg(2));
        for (const KeyPropertySpec& p : keyProperties()) closest.consider(p.word);
        const std::string_view guess = closest.best();
        error(argPos(2),
              noteCharacters("unknown key property " + quoteToken(arg(2)) +
                                 (guess.empty() ? "" : " (did you mean '" + std::string(guess) + "'?)") +
                                 "; " + expected,
                             arg(2), argPos(2)));
        return;
    }
    if (numbers != spec->numbers) {
        error(argPos(2), quoteToken(spec->word) + " takes " + std::to_string(spec->numbers) +
                             (spec->numbers == 1 ? " number (" : " numbers (") + std::string(spec->values) +
                             "), got " + std::to_string(numbers));
        return;
    }
    bool ok = true;
    const KeyTime time = keyTime(0, ok);
    const std::optional<Target> t =
        target(1, CameraTarget::Accepted, LightTarget::Accepted, ShapeTarget::Accepted);
    Vec3 values;
    switch (spec->property) {
        case KeyProperty::Colour: {
            static constexpr std::array<std::string_view, 3> kWhat = {"red", "green", "blue"};
            for (int k = 0; k < 3; ++k) {
                bool good = true;
                values[k] = real(3 + k, good);
                if (good && !(values[k] >= 0 && values[k] <= 255)) {
                    error(argPos(3 + k), std::string(kWhat[static_cast<std::size_t>(k)]) +
                                             " must be from 0 to 255, got " + printable(arg(3 + k)));
                    good = false;
                }
                ok = ok && good;
            }
            break;
        }
        case KeyProperty::Intensity:
            values.x = nonNegative(3, "light intensity", ok);
            break;
        case KeyProperty::Zoom:
            values.x = positive(3, "screen distance", ok);
            break;
        case KeyProperty::Visible: {
            bool good = true;
            values.x = float(real(3, good));
            if (good && values.x != 0 && values.x != 1) {
                error(argPos(3), "visible must be 0 or 1, got " + printable(arg(3)));
                good = false;
            }
            ok = ok && good;
            break;
        }
    }
    std::optional<Easing> mode;
    if (modeAt < argCount() && spec->property == KeyProperty::Visible) {
        // SPEC 10.7: a target shows or hides at its keys, never in between.
        error(argPos(modeAt), "'visible' keys are always a step: a mode word is not allowed here");
        ok = false;
    } else if (modeAt < argCount()) {
        mode = easing(modeAt, argCount());
        ok = ok && mode.has_value();
    }
    if (!t || !ok) return;
    if (!hasProperty(*t, spec->property)) {
        error(argPos(2), quoteToken(spec->word) + " is not a property of " + targetText(*t) + " (" +
                             quoteToken(spec->word) + " keys " + std::string(spec->targets) + ")");
        return;
    }
    addKey(*t, spec->property, time, {time.value, Pose{values, {}}, mode}, argPos(0));
}

void SceneBuilder::parseDrive() {
    if (!expectCounts()) return;
    const std::optional<Target> t =
        target(0, CameraTarget::Accepted, LightTarget::Accepted, ShapeTarget::Accepted);
    const std::optional<DriveChannel> channel = driveChannelFromWord(arg(1));
    if (!channel && !failed(1)) {
        std::string list;
        ClosestWord closest(arg(1));
        for (std::string_view c : driveChannelNames()) {
            list += " " + std::string(c);
            closest.consider(c);
        }
        const std::string_view guess = closest.best();
        error(argPos(1),
              noteCharacters("unknown channel " + quoteToken(arg(1)) +
                                 (guess.empty() ? "" : " (did you mean '" + std::string(guess) + "'?)") +
                                 "; the channels are" + list,
                             arg(1), argPos(1)));
    }
    const LogicalToken& expression = argToken(2);
    if (expression.form != TokenForm::Compiled && expression.form != TokenForm::Failed) {
        error(argPos(2), "a drive's expression stands in parentheses: write '(" +
                             std::string(expression.written) + ")'");
        return;
    }
    if (!t || !channel || expression.form != TokenForm::Compiled) return;
    const std::string_view word = driveChannelName(*channel);
    if (!hasChannel(*t, *channel)) {
        error(argPos(1), quoteToken(word) + " is not a channel of " + targetText(*t) + " (" +
                             quoteToken(word) + " drives " + channelTargets(*channel) + ")");
        return;
    }
    const TrackProperty property = *channel == DriveChannel::Intensity ? TrackProperty(KeyProperty::Intensity)
                                   : *channel == DriveChannel::D       ? TrackProperty(KeyProperty::Zoom)
                                   : *channel >= DriveChannel::R       ? TrackProperty(KeyProperty::Colour)
                                                                       : std::nullopt;
    Track& track = trackOf(*t, property);
    const auto slot = static_cast<std::size_t>(driveSlot(*channel));
    if (track.drives && track.drives->bySlot[slot]) {
        const f2::Drive& first = *track.drives->bySlot[slot];
        const std::string where = first.file == expander_.fileName(tokens_.pos.file)
                                      ? std::to_string(first.line) + ":" + std::to_string(first.column)
                                      : first.place();
        error(commandPos(), "second '/drive' of " + quoteToken(word) + " of " + targetText(*t) +
                                " (the first is at " + where + ")");
        return;
    }
    auto drive = std::make_shared<f2::Drive>();
    drive->target = targetName(*t);
    drive->channel = *channel;
    drive->expression = std::string(expression.written);
    drive->file = expander_.fileName(tokens_.pos.file);
    drive->line = commandPos().line;
    drive->column = commandPos().column;
    drive->code = tokens_.compiled;
    auto drives = std::make_shared<TrackDrives>(track.drives ? *track.drives : TrackDrives{});
    drives->bySlot[slot] = drive;
    track.drives = std::move(drives);
    drives_.push_back(std::move(drive));
}

bool SceneBuilder::hasChannel(Target t, DriveChannel c) const {
    switch (c) {
        case DriveChannel::Intensity:
            return hasProperty(t, KeyProperty::Intensity);
        case DriveChannel::D:
            return hasProperty(t, KeyProperty::Zoom);
        case DriveChannel::R:
        case DriveChannel::G:
        case DriveChannel::B:
            return hasProperty(t, KeyProperty::Colour);
        default:  // a shape has no pose of its own (SPEC 10.1)
            return t.shape < 0 &&
                   (t.light < 0 || !scene_.lightMotions[static_cast<std::size_t>(t.light)].ambient);
    }
}

std::string SceneBuilder::channelTargets(DriveChannel c) {
    switch (c) {
        case DriveChannel::Intensity:
            return std::string(findKeyProperty("intensity")->targets);
        case DriveChannel::D:
            return std::string(findKeyProperty("d")->targets);
        case DriveChannel::R:
        case DriveChannel::G:
        case DriveChannel::B:
            return "the colour of " + std::string(findKeyProperty("colour")->targets);
        default:
            return "the pose of an object, a part, the camera or a light that is not ambient (not a "
                   "shape)";
    }
}

void SceneBuilder::finishDrives() {
    for (const std::shared_ptr<f2::Drive>& drive : drives_) {
        drive->fps = scene_.fps;
        scene_.drives.push_back(drive);
    }
    drives_ = {};
}

bool SceneBuilder::hasProperty(Target t, KeyProperty property) {
    switch (property) {
        case KeyProperty::Colour:
        case KeyProperty::Visible:
            return !t.camera && t.light < 0;
        case KeyProperty::Intensity:
            return t.light >= 0;
        case KeyProperty::Zoom:
            return t.camera;
    }
    return false;
}

std::string SceneBuilder::targetText(Target t) const {
    if (t.camera) return "the camera";
    if (t.light >= 0) return lightText(t.light);
    if (t.shape >= 0) return "the shape " + quoteToken(targetName(t));
    if (t.part >= 0) return "the part " + quoteToken(targetName(t));
    const SceneObject& o = scene_.objects[t.object];
    return "the " + std::string(typeNameOf(o)) + " " + quoteToken(o.name);
}

std::optional<Easing> SceneBuilder::easing(int i, int end) {
    const std::optional<Interpolation> mode = interpolationMode(i);
    if (!mode) return std::nullopt;
    const int given = end - i - 1, wanted = modeNumberCount(*mode);
    if (given != wanted) {
        const std::string word = quoteToken(arg(i));
        error(argPos(i),
              wanted == 0 ? word + " takes no numbers after it, got " + std::to_string(given)
                          : word + " takes 4 numbers after it (x1 y1 x2 y2), got " + std::to_string(given));
        return std::nullopt;
    }
    Easing out{*mode};
    if (*mode == Interpolation::Bezier) {
        bool ok = true;
        auto unitX = [&](int k, std::string_view what) {
            bool good = true;
            const float v = real(k, good);
            if (good && !(v >= 0 && v <= 1)) {
                error(argPos(k),
                      "bezier's " + std::string(what) + " must be from 0 to 1, got " + printable(arg(k)));
                good = false;
            }
            ok = ok && good;
            return v;
        };
        out.curve.x1 = unitX(i + 1, "x1");
        out.curve.y1 = real(i + 2, ok);
        out.curve.x2 = unitX(i + 3, "x2");
        out.curve.y2 = real(i + 4, ok);
        if (!ok) return std::nullopt;
    }
    return out;
}

void SceneBuilder::addCameraKeys() {
    for (const CameraKey& k : cameraKeys_) {
        addKey(Target{0, -1, true}, std::nullopt, k.time,
               {k.time.value, k.pose.value_or(scene_.camera.pose), k.mode}, k.origin);
    }
    cameraKeys_ = {};
}

int& SceneBuilder::trackBookIndex(Target t, TrackProperty property) {
    if (property == KeyProperty::Zoom) return cameraZoomBook_;
    if (property == KeyProperty::Intensity) return lightBook(t).intensityBook;
    if (property == KeyProperty::Colour) return colourTrackBooks_[targetTrackIndex(t, *property)];
    if (property == KeyProperty::Visible) return visibilityTrackBooks_[targetTrackIndex(t, *property)];
    if (t.camera) return cameraTrackBook_;
    if (t.light >= 0) return lightBook(t).poseBook;
    return poseTrackBooks_.try_emplace(slotOf(t), -1).first->second;
}

void SceneBuilder::addKey(Target t, TrackProperty property, KeyTime time, const Key& key, Pos origin) {
    Track& track = trackOf(t, property);
    int& bookIndex = trackBookIndex(t, property);
    if (bookIndex < 0) {
        bookIndex = static_cast<int>(trackBooks_.size());
        trackBooks_.push_back({t, property, {}, true, {}});
    }
    TrackBook& book = trackBooks_[static_cast<std::size_t>(bookIndex)];
    if (time.seconds) {
        // Its place among the keys is known only with `/fps`: the track is
        // sorted at the end, and no key of it is replaced before that.
        book.sorted = false;
        book.inSeconds.push_back(static_cast<std::uint32_t>(track.keys.size()));
    }
    // Keys in increasing order (the usual case) stay sorted as they come; a
    // track that goes back is sorted once at the end, so a reversed file of
    // n keys costs O(n log n), not O(n²).
    if (book.sorted && !track.keys.empty()) {
        Key& last = track.keys.back();
        if (key.time == last.time) {
            warnReplaced(t, property, key.time, origin, book.origins.back());
            last = key;
            book.origins.back() = origin;
            return;
        }
        if (key.time < last.time) book.sorted = false;
    }
    track.keys.push_back(key);
    book.origins.push_back(origin);
}

double SceneBuilder::framesOfSeconds(double seconds, Pos origin) {
    const double frames = seconds * scene_.fps;
    if (frames > limits_.maxKeyFrame) {
        error(origin, "a key time must be at most " + std::to_string(limits_.maxKeyFrame) + " frames, got " +
                          formatNumber(seconds) + " s = " + formatNumber(frames) + " frames at " +
                          std::to_string(scene_.fps) + " fps");
    }
    return frames;
}

void SceneBuilder::convertSecondsToFrames() {
    for (std::size_t k = 0; k < scene_.captions.size(); ++k) {
        Caption& c = scene_.captions[k];
        const CaptionBook& book = captionBooks_[k];
        if (book.fromInSeconds) c.from = framesOfSeconds(c.from, book.from);
        if (book.toInSeconds) c.to = framesOfSeconds(c.to, book.to);
        if (!(c.to > c.from)) {
            error(book.to, "a caption must end after it starts: it starts at frame " + formatNumber(c.from) +
                               " and ends at frame " + formatNumber(c.to));
        }
    }
    captionBooks_ = {};
    for (TrackBook& book : trackBooks_) {
        std::vector<Key>& keys = trackOf(book.target, book.property).keys;
        for (std::uint32_t k : book.inSeconds) keys[k].time = framesOfSeconds(keys[k].time, book.origins[k]);
        book.inSeconds = {};
    }
}

void SceneBuilder::warnReplaced(Target t, TrackProperty property, double frame, Pos now, Pos before) {
    const std::string what =
        property ? "the " + std::string(keyProperties()[static_cast<std::size_t>(*property)].word) + " of " +
                       quoteToken(targetName(t))
                 : quoteToken(targetName(t));
    warning(now, "key frame " + formatNumber(frame) + " of " + what +
                     " is given again; it replaces the key at " + posText(before));
}

void SceneBuilder::applyInterpToPropertyTracks() {
    for (const TrackBook& book : trackBooks_) {
        // `visible` keys stay a step whatever the target's mode (SPEC 10.7).
        if (book.property && book.property != KeyProperty::Visible)
            trackOf(book.target, book.property).interpolation = trackOf(book.target).interpolation;
    }
}

void SceneBuilder::orderColourTracks() {
    const auto rank = [](const TargetTrack& c) { return c.shape >= 0 ? 2 : c.target.part >= 0 ? 1 : 0; };
    std::stable_sort(scene_.colourTracks.begin(), scene_.colourTracks.end(),
                     [&](const TargetTrack& a, const TargetTrack& b) { return rank(a) < rank(b); });
    colourTrackBooks_ = {};  // its indices no longer match
    colourTrackIndex_ = {};
}

void SceneBuilder::sortUnsortedTracks() {
    for (TrackBook& book : trackBooks_) {
        if (book.sorted) continue;
        const Target t = book.target;
        std::vector<Key>& keys = trackOf(t, book.property).keys;
        std::vector<std::uint32_t> order(keys.size());
        std::iota(order.begin(), order.end(), 0u);
        // Stable: keys of one frame stay in file order, so the last one wins.
        std::stable_sort(order.begin(), order.end(),
                         [&](std::uint32_t a, std::uint32_t b) { return keys[a].time < keys[b].time; });
        std::vector<Key> sorted;
        sorted.reserve(keys.size());
        Pos lastOrigin;
        for (std::uint32_t k : order) {
            if (!sorted.empty() && sorted.back().time == keys[k].time) {
                warnReplaced(t, book.property, keys[k].time, book.origins[k], lastOrigin);
                sorted.back() = keys[k];
            } else {
                sorted.push_back(keys[k]);
            }
            lastOrigin = book.origins[k];
        }
        keys = std::move(sorted);
        book.origins = {};
    }
}

}  // namespace f2::parsing
