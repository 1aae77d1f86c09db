#include "bench/lab/spd_povray.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <sstream>
#include <vector>

#include "core/error.h"

namespace rayo {
namespace {

std::string vec(const std::vector<std::string>& t, size_t first) {
    return "<" + t[first] + ", " + t[first + 1] + ", " + t[first + 2] + ">";
}

std::string vec(const glm::dvec3& v) {
    std::ostringstream s;
    s.precision(9);
    s << "<" << v.x << ", " << v.y << ", " << v.z << ">";
    return s.str();
}

std::vector<std::string> tokens(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string word; in >> word;) out.push_back(word);
    return out;
}

}  // namespace

std::string nff_to_povray(const std::string& nff, int width) {
    std::istringstream in(nff);
    std::vector<std::vector<std::string>> lines;
    for (std::string line; std::getline(in, line);) {
        if (!tokens(line).empty()) lines.push_back(tokens(line));
    }
    size_t light_count = 0;
    for (const auto& t : lines) light_count += t[0] == "l";
    std::ostringstream out;
    out.precision(9);
    out << "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n";
    glm::dvec3 from(0), at(0, 0, -1), up(0, 1, 0);
    double angle = 45;
    int texture = 0;
    auto number = [&](const std::vector<std::string>& t, size_t i) {
        if (i >= t.size()) throw InputError("nff_to_povray", "short '" + t[0] + "' line");
        return std::stod(t[i]);
    };
    auto point = [&](const std::vector<std::string>& t, size_t i) {
        return glm::dvec3(number(t, i), number(t, i + 1), number(t, i + 2));
    };
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::vector<std::string>& t = lines[i];
        const std::string& kind = t[0];
        if (kind == "b") {
            out << "background { color rgb " << vec(t, 1) << " }\n";
        } else if (kind == "from") {
            from = point(t, 1);
        } else if (kind == "at") {
            at = point(t, 1);
        } else if (kind == "up") {
            up = point(t, 1);
        } else if (kind == "angle") {
            angle = number(t, 1);
        } else if (kind == "v" || kind == "hither") {
        } else if (kind == "resolution") {
            // The end of the view: the camera, its frame widened for `width` pixels.
            const glm::dvec3 d = glm::normalize(at - from);
            const double span = 2.0 * std::tan(angle * 3.14159265358979323846 / 360.0) *
                                double(width) / double(width - 1);
            const glm::dvec3 right = glm::normalize(glm::cross(d, up)) * span;
            const glm::dvec3 cam_up = glm::normalize(glm::cross(right, d)) * span;
            out << "camera {\n  location " << vec(from) << "\n  direction " << vec(d)
                << "\n  right " << vec(right) << "\n  up " << vec(cam_up) << "\n}\n";
        } else if (kind == "l") {
            out << "light_source { " << vec(t, 1) << " color rgb "
                << 1.0 / std::sqrt(double(light_count)) << " }\n";
        } else if (kind == "f") {
            const double kd = number(t, 4), ks = number(t, 5), shine = number(t, 6),
                         transmit = number(t, 7), ior = number(t, 8);
            const double raise = transmit > 0 ? 1.0 / (1.0 - transmit) : 1.0;
            out << "#declare T" << ++texture << " = texture {\n  pigment { color rgb " << vec(t, 1);
            if (transmit > 0) out << " filter " << transmit;
            out << " }\n  finish { ambient " << 0.1 * raise << " diffuse " << kd * raise;
            if (ks > 0) out << " phong " << ks << " phong_size " << shine << " reflection " << ks;
            if (transmit > 0) out << " refraction 1.0 ior " << ior;
            out << " }\n}\n";
        } else if (kind == "s") {
            out << "sphere { " << vec(t, 1) << ", " << t.at(4) << " texture { T" << texture
                << " } }\n";
        } else if (kind == "c") {
            number(t, 8);
            out << "cone { " << vec(t, 1) << ", " << t[4] << ", " << vec(t, 5) << ", " << t[8]
                << " open texture { T" << texture << " } }\n";
        } else if (kind == "p" || kind == "pp") {
            const size_t count = static_cast<size_t>(number(t, 1));
            if (i + count >= lines.size()) throw InputError("nff_to_povray", "short polygon");
            const bool normals = kind == "pp";
            out << (normals ? "smooth_triangle { " : count == 3 ? "triangle { " : "polygon { ");
            if (!normals && count > 3) out << count + 1 << ", ";
            for (size_t v = 1; v <= count; ++v) {
                const std::vector<std::string>& p = lines[i + v];
                number(p, normals ? 5 : 2);
                out << (v > 1 ? ", " : "") << vec(p, 0) << (normals ? " " + vec(p, 3) : "");
            }
            if (!normals && count > 3) out << ", " << vec(lines[i + 1], 0);
            out << " texture { T" << texture << " } }\n";
            i += count;
        } else {
            throw InputError("nff_to_povray", "unexpected NFF line '" + kind + "'");
        }
    }
    return out.str();
}

}  // namespace rayo
