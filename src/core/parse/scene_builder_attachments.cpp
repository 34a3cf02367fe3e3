#include <algorithm>
#include <cmath>

#include "core/parse/expression.h"
#include "core/parse/number.h"
#include "core/parse/quoted_text.h"
#include "core/parse/ride_forest.h"
#include "core/parse/scene_builder.h"
#include "core/parse/suggest.h"
#include "core/parse/unusual_char.h"

namespace f2::parsing {

void SceneBuilder::parseLookAt() {
    if (!firstOnly(lookAtSeen_) || !expectCounts()) return;
    LookAt look;
    if (argCount() == 3) {
        bool ok = true;
        look.point = vec3(0, ok);
        if (!ok) return;
    } else {
        const std::optional<Target> t = target(0);
        if (!t) return;
        look.target = FrameRef{static_cast<std::uint32_t>(t->object), t->part};
    }
    scene_.camera.lookAt = look;
}

void SceneBuilder::parseAttach() {
    // `/attach <name> <target>`, or `/attach <name> <target> at <t>` (SPEC 10.7).
    if (argCount() == 3 && !failed(2) && arg(2) == kAtWord) {
        error(argPos(2), "'at' needs a time: '/attach <name> <target> at <t>'");
        return;
    }
    if (!expectCounts()) return;
    const bool timed = argCount() == 4;
    if (timed && (failed(2) || arg(2) != kAtWord)) {
        if (!failed(2)) error(argPos(2), "expected 'at' before the time, got " + quoteToken(arg(2)));
        return;
    }
    const std::string_view name = arg(0);
    const bool camera = name == kCameraName;
    const int light = failed(0) ? -1 : lightNamed(name).value_or(-1);  // -1: not a light
    std::optional<std::size_t> child;
    // A `{ … }` that failed is reported already; the parent is still checked.
    if (light >= 0) {
        noteLightUse(light, argPos(0), name);
        if (scene_.lightMotions[static_cast<std::size_t>(light)].ambient) {
            error(argPos(0),
                  quoteToken(name) + " is an ambient light: it has no position, so it cannot be attached");
            target(1);
            return;
        }
    } else if (!camera && !failed(0)) {
        if (name.find('.') != std::string_view::npos) {
            error(argPos(0), "only a whole object or the camera can be attached, got " + quoteToken(name));
        } else {
            child = existing(name, name, argPos(0), true);
        }
    }
    if (timed && (camera || light >= 0)) {
        error(argPos(2), quoteToken(name) +
                             " cannot change what it rides on: 'at' is for objects (one '/attach' of " +
                             (camera ? "the camera" : "a light") + ", from the start)");
        return;
    }
    // `world` (unless an object takes the name) is no holder: it ends a ride (SPEC 10.7).
    const bool world = !failed(1) && arg(1) == kWorldName && !names_.contains(kWorldName);
    if (world && !timed) {
        error(argPos(1),
              "'world' ends a ride, so it needs a time: '/attach <name> world at <t>' (without "
              "'/attach' an object rides on nothing)");
        return;
    }
    const std::optional<Target> parent = world ? std::optional<Target>(Target{}) : target(1);
    bool ok = true;
    const KeyTime time = timed ? keyTime(3, ok) : KeyTime{};
    if ((!camera && light < 0 && !child) || !parent || !ok) return;
    const std::optional<FrameRef> ref =
        world ? std::nullopt
              : std::optional<FrameRef>(FrameRef{static_cast<std::uint32_t>(parent->object), parent->part});
    if (timed) {
        const auto c = static_cast<std::uint32_t>(*child);
        if (ref && ref->object == c) {
            error(commandPos(),
                  quoteToken(name) + " cannot be attached to " + (ref->part < 0 ? "itself" : "its own part"));
            return;
        }
        // Its time may be in seconds: checked at the end of the file (checkAttachChanges).
        attachChangeBooks_.push_back({c, time, ref, std::string(arg(1)), commandPos(), argPos(3)});
        return;
    }
    std::optional<Pos>& seen = camera       ? cameraAttached_
                               : light >= 0 ? lightBooks_[static_cast<std::size_t>(light)].attached
                                            : books_[*child].attached;
    if (seen) {
        error(argPos(0), quoteToken(name) + " is already attached (at " + posText(*seen) +
                             "); one '/attach' per name" +
                             (child ? " without 'at' (a change of ride: '/attach " + std::string(name) +
                                          " <target> at <t>')"
                                    : std::string()));
        return;
    }
    if (camera || light >= 0) {  // nothing rides on the camera or a light, so they close no cycle
        (camera ? scene_.camera.attachedTo
                : scene_.lightMotions[static_cast<std::size_t>(light)].attachedTo) = ref;
        seen = commandPos();
        return;
    }
    const auto c = static_cast<std::uint32_t>(*child), p = ref->object;
    growSets();
    if (setTop_[findSet(p)] == c) {
        if (p == c) {
            error(commandPos(),
                  quoteToken(name) + " cannot be attached to " + (ref->part < 0 ? "itself" : "its own part"));
        } else {
            error(commandPos(), "attaching " + quoteToken(name) + " to " + quoteToken(arg(1)) +
                                    " makes a cycle: " + quoteToken(scene_.objects[p].name) +
                                    " already rides on " + quoteToken(name));
        }
        return;
    }
    joinSets(c, p);
    scene_.objects[c].attachedTo = ref;
    seen = commandPos();
}

void SceneBuilder::checkAttachChanges() {
    if (attachChangeBooks_.empty()) return;
    std::vector<AttachChangeBook>& books = attachChangeBooks_;
    for (AttachChangeBook& b : books) {
        if (b.time.seconds) b.time.value = framesOfSeconds(b.time.value, b.timePos);
    }
    // By time, file order among equal times.
    std::stable_sort(books.begin(), books.end(), [](const AttachChangeBook& a, const AttachChangeBook& b) {
        return a.time.value < b.time.value;
    });
    std::vector<bool> kept(books.size(), true);
    std::unordered_map<std::uint32_t, std::size_t> latest;  // object -> books index of its latest change
    for (std::size_t k = 0; k < books.size(); ++k) {
        const AttachChangeBook& b = books[k];
        SceneObject& object = scene_.objects[b.object];
        if (auto it = latest.find(b.object);
            it != latest.end() && books[it->second].time.value == b.time.value) {
            error(b.command, quoteToken(object.name) + " is already attached at frame " +
                                 formatNumber(b.time.value) + " (at " + posText(books[it->second].command) +
                                 "); one '/attach' per name and time");
            kept[k] = false;
            continue;
        }
        latest[b.object] = k;
        object.attachChanges.push_back({b.time.value, b.mount});
    }
    scene_.attachmentsChange = true;
    const std::size_t n = scene_.objects.size();
    // The rides as a forest that changes at each `at` time, in order: the
    // rides that change then are cut, then each new one is linked unless
    // the object is the top of its holder's tree (a cycle). O(log n) each.
    RideForest forest(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        if (const std::optional<FrameRef>& mount = scene_.objects[i].attachedTo)
            forest.link(i, mount->object);
    }
    for (std::size_t first = 0, end = 0; first < books.size() && !stopped_; first = end) {
        while (end < books.size() && books[end].time.value == books[first].time.value) ++end;
        for (std::size_t k = first; k < end; ++k) {
            if (kept[k]) forest.cut(books[k].object);
        }
        for (std::size_t k = first; k < end && !stopped_; ++k) {
            const AttachChangeBook& b = books[k];
            if (!kept[k] || !b.mount) continue;
            if (forest.top(b.mount->object) != b.object) {
                forest.link(b.object, b.mount->object);
            } else {
                reportRideCycle(b);
            }
        }
    }
    attachChangeBooks_ = {};
}

void SceneBuilder::reportRideCycle(const AttachChangeBook& b) {
    const double t = b.time.value;
    SceneObject& object = scene_.objects[b.object];
    // When the chain from the holder up to the object holds since: the
    // latest `at` on it (none: the start). The chain is at most every object long.
    std::optional<double> since;
    std::uint32_t x = b.mount->object;
    for (std::size_t steps = 0; x != b.object && steps < scene_.objects.size(); ++steps) {
        const SceneObject& holder = scene_.objects[x];
        const auto after = std::upper_bound(holder.attachChanges.begin(), holder.attachChanges.end(), t,
                                            [](double time, const AttachChange& c) { return time < c.time; });
        if (after != holder.attachChanges.begin())
            since = std::max(since.value_or(0.0), std::prev(after)->time);
        const std::optional<FrameRef> mount = mountAt(holder, t);
        if (!mount) break;
        x = mount->object;
    }
    error(b.command, "attaching " + quoteToken(object.name) + " to " + quoteToken(b.targetText) +
                         " at frame " + formatNumber(t) +
                         " makes a cycle: " + quoteToken(scene_.objects[b.mount->object].name) +
                         " rides on " + quoteToken(object.name) +
                         (since ? " from frame " + formatNumber(*since) : " from the start"));
    for (AttachChange& change : object.attachChanges) {
        if (change.time == t) change.mount.reset();
    }
}

void SceneBuilder::growSets() {
    while (setParent_.size() < scene_.objects.size()) {
        const auto i = static_cast<std::uint32_t>(setParent_.size());
        setParent_.push_back(i);
        setSize_.push_back(1);
        setTop_.push_back(i);
    }
}

std::uint32_t SceneBuilder::findSet(std::uint32_t x) {
    while (setParent_[x] != x) {
        setParent_[x] = setParent_[setParent_[x]];
        x = setParent_[x];
    }
    return x;
}

void SceneBuilder::joinSets(std::uint32_t child, std::uint32_t parent) {
    std::uint32_t a = findSet(child), b = findSet(parent);
    const std::uint32_t top = setTop_[b];
    if (setSize_[a] > setSize_[b]) std::swap(a, b);
    setParent_[a] = b;
    setSize_[b] += setSize_[a];
    setTop_[b] = top;
}

void SceneBuilder::orderAttachments() {
    if (errors_ > 0) return;
    const std::vector<SceneObject>& objects = scene_.objects;
    if (scene_.attachmentsChange) {
        for (std::uint32_t i = 0; i < objects.size(); ++i) {
            if (objects[i].mayRide()) scene_.attachOrder.push_back(i);
        }
        return;
    }
    if (setParent_.empty()) return;
    std::vector<bool> placed(objects.size(), false);
    std::vector<std::uint32_t> chain;
    for (std::uint32_t i = 0; i < objects.size(); ++i) {
        // Climb while the objects are attached and not yet placed, then place them top first.
        for (std::uint32_t x = i; objects[x].attachedTo && !placed[x]; x = objects[x].attachedTo->object) {
            placed[x] = true;
            chain.push_back(x);
        }
        scene_.attachOrder.insert(scene_.attachOrder.end(), chain.rbegin(), chain.rend());
        chain.clear();
    }
}

}  // namespace f2::parsing
