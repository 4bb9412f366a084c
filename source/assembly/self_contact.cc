// Penalty self-contact of a rod (self_contact.h, doc/theory-rod.md 9).
#include <cosmo/assembly/self_contact.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace cosmo
{
  namespace assembly
  {
    SelfContact::SelfContact(const double radius, const double stiffness, std::vector<double> weights,
                             std::vector<double> arclength, const double ring_length)
      : a(radius)
      , k(stiffness)
      , ring(ring_length)
      , w(std::move(weights))
      , s(std::move(arclength))
    {}

    bool
    SelfContact::excluded(const unsigned int i, const unsigned int j) const
    {
      double along = std::abs(s[j] - s[i]);
      if (ring > 0)
        along = std::min(along, ring - along);
      // (a relative margin for the round-off of s: a pair at exactly pi a
      // along the rod is excluded on every machine)
      return along <= M_PI * a * (1 + 1e-12);
    }

    std::vector<std::pair<unsigned int, unsigned int>>
    SelfContact::pairs_within(const std::vector<Tensor<1, 3>> &x, const double distance) const
    {
      // Cells of side `distance`: a pair closer than that lies in the same
      // or in neighbouring cells.
      std::map<std::array<long, 3>, std::vector<unsigned int>> cells;
      const auto cell_of = [&](const Tensor<1, 3> &p) {
        return std::array<long, 3>{{static_cast<long>(std::floor(p[0] / distance)),
                                    static_cast<long>(std::floor(p[1] / distance)),
                                    static_cast<long>(std::floor(p[2] / distance))}};
      };
      for (unsigned int i = 0; i < x.size(); ++i)
        cells[cell_of(x[i])].push_back(i);
      std::vector<std::pair<unsigned int, unsigned int>> pairs;
      for (unsigned int i = 0; i < x.size(); ++i)
        {
          const auto c = cell_of(x[i]);
          for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy)
              for (long dz = -1; dz <= 1; ++dz)
                {
                  const auto it = cells.find({{c[0] + dx, c[1] + dy, c[2] + dz}});
                  if (it == cells.end())
                    continue;
                  for (const unsigned int j : it->second)
                    if (j > i && !excluded(i, j) && (x[j] - x[i]).norm() < distance)
                      pairs.emplace_back(i, j);
                }
        }
      std::sort(pairs.begin(), pairs.end());
      return pairs;
    }

    std::vector<SelfContact::Term>
    SelfContact::terms(const std::vector<Tensor<1, 3>> &x) const
    {
      std::vector<Term> result;
      for (const auto &p : pairs_within(x, 2 * a))
        {
          const Tensor<1, 3> r = x[p.first] - x[p.second];
          const double       d = r.norm();
          if (!(d > 0))
            continue; // (two nodes at one point: no direction; their neighbours push them apart)
          const Tensor<1, 3> n = r / d;
          const double       g = 2 * a - d, c = w[p.first] * w[p.second] * k;
          // E = c g^3/3: dE/dx_i = -c g^2 n, and d2E/dx_i2 = c (2 g n n - g^2/d (I - n n)).
          Term term;
          term.i          = p.first;
          term.j          = p.second;
          term.energy     = c * g * g * g / 3;
          term.gradient_i = -c * g * g * n;
          const Tensor<2, 3> nn = outer_product(n, n);
          term.hessian          = c * (2 * g * nn - g * g / d * (Tensor<2, 3>(unit_symmetric_tensor<3>()) - nn));
          result.push_back(term);
        }
      return result;
    }

    double
    SelfContact::smallest_gap(const std::vector<Tensor<1, 3>> &x) const
    {
      double gap = std::numeric_limits<double>::infinity();
      for (const auto &p : pairs_within(x, 4 * a))
        gap = std::min(gap, (x[p.first] - x[p.second]).norm() - 2 * a);
      return gap;
    }
  } // namespace assembly
} // namespace cosmo
