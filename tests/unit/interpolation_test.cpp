// Interpolation per key (SPEC 9.3, 10.4): every mode's weight at hand-computed
// fractions, modes per key and per target, spline neighbours of any mode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/anim/frame_builder.h"
#include "core/anim/track.h"
#include "core/parse/language.h"
#include "test_scenes.h"

namespace f2 {
namespace {

using test::sceneFromText;

/// x of object `s` (the only object) at time t.
float xAt(const SceneDesc& scene, double t) { return objectFrame(scene.objects.at(0), t).translation.x; }

struct ModeCase {
    Interpolation mode;
    double at25, at75;  // w(0.25), w(0.75) worked out by hand
};

// linear u; ease 3u²−2u³: 3/16 − 2/64 = 0.15625, 27/16 − 54/64 = 0.84375;
// ease_in u³: 1/64, 27/64; ease_out 1 − (1−u)³: 1 − 27/64, 1 − 1/64; step 0.
// SPEC 10.4: back 1 + c₃(u−1)³ + c₁(u−1)², (u−1)³ = −27/64, −1/64 and
// (u−1)² = 9/16, 1/16; elastic: the sine's angle (10u − 0.75)·120° is 210°
// (sin −1/2) and 810° (sin 1); bounce n·u² = 7.5625/16 below 1/d, and at 0.75
// (between 2/d and 2.5/d) n(0.75 − 2.25/2.75)² + 0.9375 = 7.5625·(3/44)² + 0.9375.
constexpr double kC1 = 1.70158, kC3 = kC1 + 1.0;
const ModeCase kModes[] = {
    {Interpolation::Linear, 0.25, 0.75},
    {Interpolation::Ease, 0.15625, 0.84375},
    {Interpolation::EaseIn, 0.015625, 0.421875},
    {Interpolation::EaseOut, 0.578125, 0.984375},
    {Interpolation::Step, 0.0, 0.0},
    {Interpolation::Back, 1.0 - kC3 * 27.0 / 64.0 + kC1 * 9.0 / 16.0, 1.0 - kC3 / 64.0 + kC1 / 16.0},
    {Interpolation::Elastic, 1.0 - 0.5 * std::exp2(-2.5), 1.0 + std::exp2(-7.5)},
    {Interpolation::Bounce, 7.5625 / 16.0, 7.5625 * 9.0 / 1936.0 + 0.9375},
};

TEST(Interpolation, EveryModeOfTheLanguageIsTested) {
    for (Interpolation mode : interpolationModes()) {
        if (mode == Interpolation::Spline) continue;  // not a blend of two keys (tests below)
        SCOPED_TRACE(std::string(interpolationName(mode)));
        EXPECT_TRUE(std::any_of(std::begin(kModes), std::end(kModes),
                                [&](const ModeCase& c) { return c.mode == mode; }));
    }
}

TEST(Interpolation, BackAndElasticOvershootBounceStaysAtOrBelowOne) {
    double backMost = 0, elasticMost = 0, bounceMost = 0;
    for (int i = 0; i <= 1000; ++i) {
        const double u = i / 1000.0;
        backMost = std::max(backMost, backFraction(u));
        elasticMost = std::max(elasticMost, elasticFraction(u));
        bounceMost = std::max(bounceMost, bounceFraction(u));
    }
    EXPECT_GT(backMost, 1.09);  // the classic 10 % overshoot
    EXPECT_LT(backMost, 1.11);
    EXPECT_GT(elasticMost, 1.03);
    EXPECT_LE(bounceMost, 1.0 + 1e-12);
    EXPECT_DOUBLE_EQ(bounceFraction(1.0 / 2.75), 1.0);  // the first touch of the ground
}

TEST(Interpolation, WeightOfEveryModeAtAQuarterAndThreeQuarters) {
    for (const ModeCase& c : kModes) {
        SCOPED_TRACE(std::string(interpolationName(c.mode)));
        EXPECT_DOUBLE_EQ(interpolationWeight(c.mode, 0.25), c.at25);
        EXPECT_DOUBLE_EQ(interpolationWeight(c.mode, 0.75), c.at75);
        EXPECT_DOUBLE_EQ(interpolationWeight(c.mode, 0.0), 0.0);
        if (c.mode != Interpolation::Step) {
            EXPECT_DOUBLE_EQ(interpolationWeight(c.mode, 1.0), 1.0);
        }
    }
}

TEST(Interpolation, ModeWordOnTheKeyMovesTheTargetToTheNextKey) {
    for (const ModeCase& c : kModes) {
        const std::string name(interpolationName(c.mode));
        SCOPED_TRACE(name);
        // Keys 0 and 8 from x = 0 to x = 64: u = 0.25 at frame 2, 0.75 at frame 6.
        const SceneDesc s =
            sceneFromText("/sphere s 1 0 0 0\n/key 0 s 0 0 0 0 0 0 " + name + "\n/key 8 s 64 0 0 0 0 0\n");
        EXPECT_FLOAT_EQ(xAt(s, 2), float(64 * c.at25));
        EXPECT_FLOAT_EQ(xAt(s, 6), float(64 * c.at75));
        EXPECT_FLOAT_EQ(xAt(s, 8), 64);  // step holds P1 until P2's frame, then P2
        // The same mode for the whole target with /interp.
        const SceneDesc t = sceneFromText("/sphere s 1 0 0 0\n/interp s " + name +
                                          "\n/key 0 s 0 0 0 0 0 0\n/key 8 s 64 0 0 0 0 0\n");
        EXPECT_FLOAT_EQ(xAt(t, 2), float(64 * c.at25));
        EXPECT_FLOAT_EQ(xAt(t, 6), float(64 * c.at75));
    }
}

TEST(Interpolation, StepHoldsUntilTheNextKeysFrame) {
    const SceneDesc s =
        sceneFromText("/sphere s 1 0 0 0\n/key 0 s 0 0 0 0 0 0 step\n/key 10 s 50 0 0 0 0 0\n");
    EXPECT_EQ(xAt(s, 9.999), 0);
    EXPECT_EQ(xAt(s, 10), 50);
}

TEST(Interpolation, KeyModeOverridesTheTargetsInterpWhereverItStands) {
    // /interp after the keys still applies to the keys without a mode.
    const SceneDesc s = sceneFromText(
        "/sphere s 1 0 0 0\n"
        "/key 0 s 0 0 0 0 0 0\n"
        "/key 4 s 64 0 0 0 0 0 linear\n"
        "/key 8 s 128 0 0 0 0 0\n"
        "/interp s ease_in\n");
    EXPECT_FLOAT_EQ(xAt(s, 2), 64 * 0.125f);  // ease_in at u = 1/2: 1/8
    EXPECT_FLOAT_EQ(xAt(s, 6), 96);           // linear at u = 1/2
    ASSERT_EQ(s.objects[0].track.keys.size(), 3u);
    EXPECT_EQ(s.objects[0].track.modeAfter(0), Interpolation::EaseIn);
    EXPECT_EQ(s.objects[0].track.modeAfter(1), Interpolation::Linear);
}

TEST(Interpolation, SplineNeighboursAreTheKeysAroundWhateverTheirModes) {
    // Keys x = 0 (linear), 10 (spline), 30 (step), 50. The spline segment
    // 10..20 uses P0 = 0, P1 = 10, P2 = 30, P3 = 50: at u = 1/2
    // ½(2·10 + 30·½ + (0 − 50 + 120 − 50)·¼ + (30 − 0 − 90 + 50)·⅛) = 19.375.
    const SceneDesc s = sceneFromText(
        "/sphere s 1 0 0 0\n"
        "/key 0 s 0 0 0 0 0 0 linear\n"
        "/key 10 s 10 0 0 0 0 0 spline\n"
        "/key 20 s 30 0 0 0 0 0 step\n"
        "/key 30 s 50 0 0 0 0 0\n");
    EXPECT_FLOAT_EQ(xAt(s, 5), 5);  // linear
    EXPECT_FLOAT_EQ(xAt(s, 15), 19.375f);
    EXPECT_FLOAT_EQ(xAt(s, 25), 30);  // step
    EXPECT_FLOAT_EQ(xAt(s, 30), 50);
}

TEST(Interpolation, PartKeysAndRestKeysTakeModesToo) {
    const SceneDesc s = sceneFromText(
        "/robot r 0 0 0\n"
        "/key 0 r.head ease_out\n"
        "/key 4 r.head 0 0 0 0 64 0\n");
    const Track& head = s.objects[0].partTracks[std::size_t(PartId::Head)];
    ASSERT_EQ(head.keys.size(), 2u);
    EXPECT_EQ(head.keys[0].pose, Pose{});
    EXPECT_FLOAT_EQ(evaluateTrack(head, 1, Pose{}).rotation.y, float(64 * 0.578125));
}

}  // namespace
}  // namespace f2
