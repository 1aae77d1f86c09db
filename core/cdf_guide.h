#pragma once
// A guide table for inverting a discrete CDF in expected constant time (Chen & Asau 1974, the
// "cutpoint method"): the running sums of n weights are cut into n equal buckets of u ∈ [0, 1),
// and each bucket remembers the first index whose running sum exceeds its lower end, so that a
// lookup starts there and steps forward about once instead of binary-searching all n sums. The
// answer is std::upper_bound's over the same sums, bit for bit (the float target is the same;
// the guide only says where to start looking), so a sampler keeps its pictures when it takes
// one. No allocation per lookup; the table is n 32-bit indices.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rayo {

class CdfGuide {
  public:
    // Builds the table for `cdf`, the non-decreasing running sums of the weights (cdf.back() the
    // total). Rebuild it whenever the sums change.
    void build(const std::vector<float>& cdf) {
        m_start.clear();
        const size_t n = cdf.size();
        if (n == 0 || n > UINT32_MAX) return;
        const double total = cdf.back();
        m_start.resize(n);
        for (size_t k = 0; k < n; ++k) {
            // The bucket's lower end k/n·W, taken one float low so that rounding never starts a
            // search past its answer (find() checks that too).
            const float low =
                std::nextafter(static_cast<float>(total * double(k) / double(n)), -1.0f);
            m_start[k] =
                static_cast<uint32_t>(std::upper_bound(cdf.begin(), cdf.end(), low) - cdf.begin());
        }
    }

    // Whether the table was built for sums of `cdf`'s size.
    bool built_for(const std::vector<float>& cdf) const {
        return !cdf.empty() && m_start.size() == cdf.size();
    }

    // std::upper_bound(cdf, target) for target = u·cdf.back(), u ∈ [0, 1]: the first index
    // whose running sum exceeds the target (cdf.size() when none does). Falls back to the binary
    // search when the table was not built for `cdf`.
    size_t find(const std::vector<float>& cdf, float u, float target) const {
        const size_t n = cdf.size();
        if (!built_for(cdf)) {
            return static_cast<size_t>(std::upper_bound(cdf.begin(), cdf.end(), target) -
                                       cdf.begin());
        }
        const float scaled = u * static_cast<float>(n);
        const size_t bucket = scaled > 0.0f ? std::min(static_cast<size_t>(scaled), n - 1) : 0;
        size_t i = m_start[bucket];
        if (i > 0 && cdf[i - 1] > target) {
            // The target lies below the bucket's start (u rounded up into this bucket, or a
            // target rounded below u·W): search the sums before it.
            return static_cast<size_t>(
                std::upper_bound(cdf.begin(), cdf.begin() + static_cast<std::ptrdiff_t>(i),
                                 target) -
                cdf.begin());
        }
        while (i < n && !(cdf[i] > target)) ++i;
        return i;
    }

  private:
    std::vector<uint32_t> m_start;  // per bucket: the first index to look at
};

}  // namespace rayo
