#pragma once
/// The robot's and the human's parts (SPEC 5), as indices in their models'
/// order of parts (core/scene/models.cpp), for tests that name them.
namespace f2::test {

struct RobotPart {
    static constexpr int Body = 0, Head = 1, LHand = 2, RHand = 3;
};

}  // namespace f2::test
