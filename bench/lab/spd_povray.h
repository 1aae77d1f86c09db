#pragma once
// NFF text as a POV-Ray 3.7 scene, for `rayo bench suite --povray`: the conventions of the
// SPD's own POV-Ray translations (../shared/spd/README.md; the SPD's reference reader):
// ambient 0.1 and diffuse Kd of the colour, Phong highlight Ks with exponent Shine and mirror
// reflection Ks, a filtering surface (T > 0) with filter T, refraction at the NFF index and
// ambient and diffuse raised by 1/(1 − T) (POV-Ray scales them by 1 − filter, NFF does not);
// each of the N lights at 1/sqrt(N) (what an NFF reader applies itself); linear colours
// (assumed_gamma 1). The frame is widened by W/(W − 1) for W pixels: NFF's angle spans the
// centres of the edge pixels, POV-Ray's camera the image edges. Reads the subset of NFF the
// SPD generators write (b, v, l, f, s, c, p, pp); throws InputError on anything else.
#include <string>

namespace rayo {

std::string nff_to_povray(const std::string& nff, int width);

}  // namespace rayo
