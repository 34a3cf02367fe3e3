// Interpolation per key (SPEC 9.3, 10.4): every mode's weight at hand-computed
// fractions, modes per key and per target, spline neighbours of any mode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/anim/frame_builder.h"
#include "core/anim/track.h"
#include "core/parse/language.h"
#include "robot_parts.h"
#include "test_scenes.h"

namespace f2 {

using test::RobotPart;
namespace {

using test::sceneFromText;

/// x of object `s` (the only object) at time t.
float xAt(const SceneDesc& scene, double t) { return objectFrame(scene.objects.at(0), t).translation.x; }

struct ModeCase {
    Easing easing;
    double at25, at75;       // w(0.25), w(0.75) worked out by hand
    double tolerance = 0.0;  // 0: to the last bits (EXPECT_DOUBLE_EQ)
};

// linear u; ease 3u²−2u³: 3/16 − 2/64 = 0.15625, 27/16 − 54/64 = 0.84375;
// ease_in u³: 1/64, 27/64; ease_out 1 − (1−u)³: 1 − 27/64, 1 − 1/64; step 0.
// SPEC 10.4: back 1 + c₃(u−1)³ + c₁(u−1)², (u−1)³ = −27/64, −1/64 and
// (u−1)² = 9/16, 1/16; elastic: the sine's angle (10u − 0.75)·120° is 210°
// (sin −1/2) and 810° (sin 1); bounce n·u² = 7.5625/16 below 1/d, and at 0.75
// (between 2/d and 2.5/d) n(0.75 − 2.25/2.75)² + 0.9375 = 7.5625·(3/44)² + 0.9375.
// bezier with x1 = 1/3, x2 = 2/3 has x(s) = s, so w(u) = y(u): with y1 = 0,
// y2 = 1 that is 3u² − 2u³ again (to the float rounding of 1/3 and 2/3 and
// the search's 1e-9 in s); with y1 = 1.5, y2 = −0.5, w = 4.5u(1−u)² − 1.5u²(1−u) + u³ = 4.5u − 10.5u² + 7u³:
// 0.578125 and 0.421875.
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
    {{Interpolation::Bezier, {1.0f / 3, 0, 2.0f / 3, 1}}, 0.15625, 0.84375, 1e-7},
    {{Interpolation::Bezier, {1.0f / 3, 1.5f, 2.0f / 3, -0.5f}}, 0.578125, 0.421875, 1e-7},
};

TEST(Interpolation, EveryModeOfTheLanguageIsTested) {
    for (Interpolation mode : interpolationModes()) {
        if (mode == Interpolation::Spline) continue;  // not a blend of two keys (tests below)
        SCOPED_TRACE(std::string(interpolationName(mode)));
        EXPECT_TRUE(std::any_of(std::begin(kModes), std::end(kModes),
                                [&](const ModeCase& c) { return c.easing.mode == mode; }));
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
        SCOPED_TRACE(easingText(c.easing));
        if (c.tolerance > 0) {
            EXPECT_NEAR(interpolationWeight(c.easing, 0.25), c.at25, c.tolerance);
            EXPECT_NEAR(interpolationWeight(c.easing, 0.75), c.at75, c.tolerance);
        } else {
            EXPECT_DOUBLE_EQ(interpolationWeight(c.easing, 0.25), c.at25);
            EXPECT_DOUBLE_EQ(interpolationWeight(c.easing, 0.75), c.at75);
        }
        EXPECT_DOUBLE_EQ(interpolationWeight(c.easing, 0.0), 0.0);
        if (c.easing.mode != Interpolation::Step) {
            EXPECT_DOUBLE_EQ(interpolationWeight(c.easing, 1.0), 1.0);
        }
    }
}

TEST(Interpolation, BezierIsCssCubicBezier) {
    // CSS's `ease`, cubic-bezier(0.25, 0.1, 0.25, 1): at s = 1/4 the curve is at
    // x = 3·(9/16)·(1/4)·0.25 + 3·(3/4)·(1/16)·0.25 + 1/64 = 0.15625,
    // y = 3·(9/16)·(1/4)·0.1 + 3·(3/4)·(1/16) + 1/64 = 0.1984375; at s = 1/2,
    // x = 3/8·0.25 + 3/8·0.25 + 1/8 = 0.3125, y = 3/8·0.1 + 3/8 + 1/8 = 0.5375.
    const BezierCurve ease{0.25f, 0.1f, 0.25f, 1.0f};
    EXPECT_NEAR(bezierFraction(ease, 0.15625), 0.1984375, 1e-7);
    EXPECT_NEAR(bezierFraction(ease, 0.3125), 0.5375, 1e-7);
    // Monotonic in u for a curve whose y stays in [0, 1], and exact at the ends.
    double before = 0;
    for (int i = 1; i <= 100; ++i) {
        const double w = bezierFraction(ease, i / 100.0);
        EXPECT_GE(w, before);
        before = w;
    }
    EXPECT_EQ(bezierFraction(ease, 0.0), 0.0);
    EXPECT_EQ(bezierFraction(ease, 1.0), 1.0);
    // y beyond [0, 1] overshoots, as CSS's does.
    EXPECT_GT(bezierFraction({0.5f, 0.0f, 0.5f, 1.6f}, 0.8), 1.0);
}

TEST(Interpolation, SecondsAndFractionalKeyTimesAtExactFrames) {
    // SPEC 10.4: 1.5 s at 30 fps is frame 45, /fps standing after the key;
    // (1/8)s = 3.75 frames; between frames 3.75 and 45 linearly, at frame
    // 24.375 (halfway) x is 50. The last frame is the whole number at or after 45.
    const SceneDesc s =
        sceneFromText("/sphere s 1 0 0 0\n/key (1/8)s s\n/key 1.5s s 100 0 0 0 0 0\n/fps 30\n");
    ASSERT_EQ(s.objects[0].track.keys.size(), 2u);
    EXPECT_EQ(s.objects[0].track.keys[0].time, 3.75);
    EXPECT_EQ(s.objects[0].track.keys[1].time, 45.0);
    EXPECT_EQ(s.lastFrame(), 45);
    EXPECT_FLOAT_EQ(xAt(s, 24.375), 50.0f);
    EXPECT_FLOAT_EQ(xAt(s, 3.75), 0.0f);
    // Fractional frames: a key at 2.5 with ease_in to 12.5: at frame 7.5 u = 1/2, w = 1/8.
    const SceneDesc f = sceneFromText("/sphere s 1 0 0 0\n/key 2.5 s ease_in\n/key 12.5 s 80 0 0 0 0 0\n");
    EXPECT_FLOAT_EQ(xAt(f, 7.5), 10.0f);
    EXPECT_EQ(f.lastFrame(), 13);  // the smallest whole number >= 12.5
    // Keys in seconds and in frames sort together: 0.5 s (12 frames at the
    // default 24 fps) comes before frame 20, written first.
    const SceneDesc m =
        sceneFromText("/sphere s 1 0 0 0\n/key 20 s 20 0 0 0 0 0\n/key 0.5s s 12 0 0 0 0 0\n");
    ASSERT_EQ(m.objects[0].track.keys.size(), 2u);
    EXPECT_EQ(m.objects[0].track.keys[0].time, 12.0);
    EXPECT_EQ(m.objects[0].track.keys[1].time, 20.0);
}

TEST(Interpolation, BezierKeysMoveAlongTheCurve) {
    // The second curve of the table: w(1/4) = 0.578125 of the way from 0 to 64 at frame 2.5 of 0..10.
    const SceneDesc s =
        sceneFromText("/sphere s 1 0 0 0\n/key 0 s bezier (1/3) 1.5 (2/3) -0.5\n/key 10 s 64 0 0 0 0 0\n");
    EXPECT_NEAR(xAt(s, 2.5), 0.578125 * 64, 1e-5);
    const SceneDesc i = sceneFromText(
        "/sphere s 1 0 0 0\n/interp s bezier (1/3) 1.5 (2/3) -0.5\n/key 0 s\n/key 10 s 64 0 0 0 0 0\n");
    EXPECT_NEAR(xAt(i, 2.5), 0.578125 * 64, 1e-5);
}

TEST(Interpolation, ModeWordOnTheKeyMovesTheTargetToTheNextKey) {
    for (const ModeCase& c : kModes) {
        const std::string name = easingText(c.easing);  // "bezier 0.33333334 0 0.6666667 1" for a curve
        SCOPED_TRACE(name);
        // x as far as the weight of the case says; the tolerance of the case, in units of 64.
        auto expectX = [&](const SceneDesc& scene, double t, double weight) {
            if (c.tolerance > 0)
                EXPECT_NEAR(xAt(scene, t), 64 * weight, 64 * c.tolerance + 1e-5);
            else
                EXPECT_FLOAT_EQ(xAt(scene, t), float(64 * weight));
        };
        // Keys 0 and 8 from x = 0 to x = 64: u = 0.25 at frame 2, 0.75 at frame 6.
        const SceneDesc s =
            sceneFromText("/sphere s 1 0 0 0\n/key 0 s 0 0 0 0 0 0 " + name + "\n/key 8 s 64 0 0 0 0 0\n");
        expectX(s, 2, c.at25);
        expectX(s, 6, c.at75);
        EXPECT_FLOAT_EQ(xAt(s, 8), 64);  // step holds P1 until P2's frame, then P2
        // The same mode for the whole target with /interp.
        const SceneDesc t = sceneFromText("/sphere s 1 0 0 0\n/interp s " + name +
                                          "\n/key 0 s 0 0 0 0 0 0\n/key 8 s 64 0 0 0 0 0\n");
        expectX(t, 2, c.at25);
        expectX(t, 6, c.at75);
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
    const Track& head = s.objects[0].partTracks[std::size_t(RobotPart::Head)];
    ASSERT_EQ(head.keys.size(), 2u);
    EXPECT_EQ(head.keys[0].pose, Pose{});
    EXPECT_FLOAT_EQ(evaluateTrack(head, 1, Pose{}).rotation.y, float(64 * 0.578125));
}

}  // namespace
}  // namespace f2
