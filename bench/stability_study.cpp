// The sphere stability study as a program (docs/stability.md): every sweep of
// core/sphere_stability — distance/radius, grazing rays, origins on the surface, sphere scale and
// position, the breaking point, and the spawned-ray offsets — written as CSV.
//   build/stability_study [DIR]   (default: the current directory)
// writes DIR/stability_study.csv, DIR/stability_offsets.csv and DIR/quadric_stability.csv (the
// sphere written as a quadric shape); tests/lab/sphere_stability_test.cpp runs the same
// functions and pins what they find.
#include <fstream>
#include <iostream>
#include <string>

#include "bench/lab/sphere_stability.h"
#include "shading/integrators/whitted.h"

int main(int argc, char** argv) {
    if (argc > 2 || (argc == 2 && std::string(argv[1]).rfind("-", 0) == 0)) {
        std::cerr << "usage: stability_study [DIR]\n";
        return 2;
    }
    const std::string dir = argc == 2 ? argv[1] : ".";
    const std::string accuracy_path = dir + "/stability_study.csv";
    const std::string offsets_path = dir + "/stability_offsets.csv";
    const std::string quadric_path = dir + "/quadric_stability.csv";
    std::ofstream accuracy(accuracy_path), offsets(offsets_path), quadric(quadric_path);
    if (!accuracy || !offsets || !quadric) {
        std::cerr << "stability_study: cannot write in " << dir << "\n";
        return 1;
    }
    rayo::write_csv(accuracy, rayo::run_stability_study(rayo::StabilityConfig{}));
    rayo::write_csv(offsets, rayo::run_offset_sweep(rayo::OffsetConfig{}, rayo::offset_ray_origin));
    rayo::write_csv(quadric, rayo::run_quadric_study(rayo::StabilityConfig{}));
    if (!accuracy || !offsets || !quadric) {
        std::cerr << "stability_study: write failed in " << dir << "\n";
        return 1;
    }
    std::cout << "wrote " << accuracy_path << ", " << offsets_path << " and " << quadric_path
              << "\n";
    return 0;
}
