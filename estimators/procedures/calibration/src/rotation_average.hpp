// The robust rotation average of the 24-position procedure (private): the four turntable
// rotations of a face, checked against each other before they are averaged.
//
// A table top tilted by t turns with the turntable: each raw channel of a face reads
// m + alpha cos r + beta sin r over the rotations r (exactly: the tilt enters linearly through the
// rotation), so u0 - u90 + u180 - u270 is zero but for noise whatever the tilt. A station that
// was misplaced (or moved) breaks that. The station is found by its reading along the face's up
// axis, which a misplacement of d lowers by g (1 - cos d) and a tilt does not change; it is
// dropped and the face's mean comes from the other three with the tilt's sinusoid. When it
// cannot be told which station is at fault, or two are, the run is refused.
#pragma once

#include <string>
#include <vector>

#include "plumb/calibration/triad_fit.hpp"
#include "plumb/calibration/types.hpp"

namespace plumb::calibration::detail {

struct RotationAverage {
  FaceAverages faces;
  std::vector<std::string> dropped;   // one line per station left out, with why
};

// slots: 24 stations of one run, index face * 4 + rotation / 90, all present.
// context: "run '25C': " (or empty). suspects: stations known to be off for another reason (a
// temperature far from the run's): when the rotations disagree and exactly one suspect is in the
// face, it is the one dropped. Throws CalibrationError naming the face and its stations.
RotationAverage robust_rotation_average(const std::vector<const StationAverage*>& slots, const std::string& context,
                                        const std::vector<const StationAverage*>& suspects = {});

}  // namespace plumb::calibration::detail
