// A rigid motion imposed on walls and fixed particles: translation with a constant velocity and
// rotation with a constant angular velocity about an axis through a centre that moves with the
// translation. Positions are advanced with an exact rotation (no drift off the circle), and the
// velocity of a point x is v + w x (x - centre).
#pragma once

#include "Math/Vector.h"

namespace talus {

struct PrescribedMotion {
    Vec3 velocity = Vec3::Zero();
    Vec3 angularVelocity = Vec3::Zero();
    Vec3 centre = Vec3::Zero();  // a point on the rotation axis, at the current time

    // Rotation of one time step, as a matrix (identity when not rotating).
    Mat3 stepRotation(double dt) const {
        const double angle = angularVelocity.norm() * dt;
        if (angle == 0) return Mat3::Identity();
        return Eigen::AngleAxisd(angle, angularVelocity.normalized()).toRotationMatrix();
    }
    // Where the point x is after the step with rotation R (the centre is advanced separately).
    Vec3 moved(const Vec3& x, const Mat3& R, double dt) const { return centre + R * (x - centre) + velocity * dt; }
    Vec3 pointVelocity(const Vec3& x) const { return velocity + angularVelocity.cross(x - centre); }
    void advanceCentre(double dt) { centre += velocity * dt; }
};

}  // namespace talus
