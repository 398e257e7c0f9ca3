// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/model/chain_design.h"

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <deque>
#include <mutex>
#include <numeric>
#include <optional>
#include <random>
#include <type_traits>
#include <utility>

#include "core/model/mass_chain.h"
#include "core/numbers/eigen_quad.h"
#include "core/numbers/scalar.h"

namespace grazelab::core {
namespace {

using Complex = std::complex<double>;
using ComplexVector = Eigen::VectorXcd;
using ComplexMatrix = Eigen::MatrixXcd;

// The problem scaled to numbers near 1: masses over the largest, eigenvalues n_j^2 / n_max^2
// (w0 = 1 / n_max at unit stiffness scale). The unknowns are the compliances c_i = 1 / k_i of
// that scaled chain.
// In double for the search; in binary128 to refine a design for a chain given in binary128.
template <typename R>
struct BasicScaled {
  std::vector<R> masses;
  std::vector<R> lambdas;
  /// a right wall: its compliance over c_1 (k_1 / k_(N+1), scale-free); 0 without one
  R rightRatio = 0;
};
using Scaled = BasicScaled<double>;

// u_0(lambda; c) of the chain: the displacement the wall would need for a free vibration at
// eigenvalue lambda with u_N = 1. Walking from the free end, the force in spring i is the
// inertia of the masses i..N, S_i = sum_(j >= i) lambda m_j u_j, and u_(i-1) = u_i - c_i S_i;
// lambda is an eigenvalue exactly when u_0 = 0. Affine in each c_i. With a right wall of
// compliance c_(N+1) = rho c_1 the walk starts from its spring's force -u_N / c_(N+1): all of
// it times c_(N+1) (u_N = rho c_1, force -1), which makes u_0 quadratic in c_1 and still affine
// in the others. With `gradient`, its derivatives in c as well (forward mode).
template <typename T, typename R>
T wallDisplacement(const std::vector<R>& masses, const R& lambda, const R& rightRatio, const std::vector<T>& c,
                   std::vector<T>* gradient) {
  const std::size_t n = masses.size();
  const bool wall = rightRatio > 0;
  T u = wall ? T(rightRatio) * c[0] : T(1);
  T force = wall ? T(-1) : T(0);
  // reused by the thread's calls: a design tracks thousands of points, and these vectors' malloc
  // and free took a fifth of its time
  thread_local std::vector<T> du, dForce;
  du.assign(gradient ? n : 0, T(0));
  dForce.assign(gradient ? n : 0, T(0));
  if (gradient && wall) du[0] = T(rightRatio);
  for (std::size_t i = n; i-- > 0;) {
    force += T(lambda * masses[i]) * u;
    if (gradient) {
      for (std::size_t k = 0; k < n; ++k) dForce[k] += T(lambda * masses[i]) * du[k];
      for (std::size_t k = 0; k < n; ++k) du[k] -= c[i] * dForce[k];
      du[i] -= force;
    }
    u -= c[i] * force;
  }
  if (gradient) gradient->assign(du.begin(), du.end());
  return u;
}

// F(c) and its Jacobian: one equation per eigenvalue.
template <typename T, typename R>
void target(const BasicScaled<R>& scaled, const std::vector<T>& c, Eigen::Matrix<T, Eigen::Dynamic, 1>& value,
            Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>* jacobian) {
  const std::size_t n = scaled.masses.size();
  value.resize(Eigen::Index(n));
  if (jacobian) jacobian->resize(Eigen::Index(n), Eigen::Index(n));
  thread_local std::vector<T> gradient;
  for (std::size_t j = 0; j < n; ++j) {
    value[Eigen::Index(j)] = wallDisplacement(scaled.masses, scaled.lambdas[j], scaled.rightRatio, c, jacobian ? &gradient : nullptr);
    if (jacobian) {
      for (std::size_t k = 0; k < n; ++k) (*jacobian)(Eigen::Index(j), Eigen::Index(k)) = gradient[k];
    }
  }
}

// The start system G_j(c) = prod_i (c_i - r_ij): affine in each c_i like F, with the N! roots
// c_(p(j)) = r_(p(j), j), one for each permutation p. With a right wall F is quadratic in c_1,
// and so is G: its factor in c_1 is (c_1 - r_1j)(c_1 - q_j), and each permutation has two
// roots (c_1 = r or q in the equation that fixes c_1): 2 N! in all.
struct StartSystem {
  ComplexMatrix r;    // r(i, j)
  ComplexVector q;    // q_j: the second root in c_1 (empty without a right wall)
  Complex factor(const ComplexVector& c, Eigen::Index i, Eigen::Index j) const {
    return i == 0 && q.size() ? (c[0] - r(0, j)) * (c[0] - q[j]) : c[i] - r(i, j);
  }
  Complex slope(const ComplexVector& c, Eigen::Index i, Eigen::Index j) const {
    return i == 0 && q.size() ? 2.0 * c[0] - r(0, j) - q[j] : Complex(1);
  }
  void evaluate(const ComplexVector& c, ComplexVector& value, ComplexMatrix& jacobian) const {
    const Eigen::Index n = c.size();
    value.resize(n);
    jacobian.resize(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {
      Complex product = 1;
      for (Eigen::Index i = 0; i < n; ++i) product *= factor(c, i, j);
      value[j] = product;
      for (Eigen::Index i = 0; i < n; ++i) {
        Complex others = slope(c, i, j);
        for (Eigen::Index k = 0; k < n; ++k) {
          if (k != i) others *= factor(c, k, j);
        }
        jacobian(j, i) = others;
      }
    }
  }
};

struct Homotopy {
  const Scaled& scaled;
  const StartSystem& start;
  Complex gamma;
  // H(c, t) = (1 - t) gamma G(c) + t F(c), its Jacobian in c and its derivative in t
  void evaluate(const ComplexVector& c, double t, ComplexVector& h, ComplexMatrix& hc, ComplexVector* ht) const {
    thread_local ComplexVector g, f;  // (reused: no allocation once sized)
    thread_local ComplexMatrix gc, fc;
    thread_local std::vector<Complex> cs;
    start.evaluate(c, g, gc);
    cs.assign(c.data(), c.data() + c.size());
    target(scaled, cs, f, &fc);
    h = (1 - t) * gamma * g + t * f;
    hc = (1 - t) * gamma * gc + t * fc;
    if (ht) *ht = f - gamma * g;
  }
  // dc/dt on the path through (c, t)
  std::optional<ComplexVector> tangent(const ComplexVector& c, double t) const {
    thread_local ComplexVector h, ht;
    thread_local ComplexMatrix hc;
    thread_local Eigen::PartialPivLU<ComplexMatrix> lu;
    evaluate(c, t, h, hc, &ht);
    lu.compute(hc);
    ComplexVector dc = -lu.solve(ht);
    if (!dc.allFinite()) return std::nullopt;
    return dc;
  }
};

enum class PathEnd { Finite, Infinite, Failed };

struct TrackedPath {
  PathEnd end = PathEnd::Failed;
  ComplexVector c;
};

// Follows one path from t = 0 to t = 1: fourth-order Runge-Kutta along the tangent, then Newton
// at the new t; a step whose corrector does not contract fast (the sign of a jump to another
// path) is halved.
TrackedPath track(const Homotopy& homotopy, ComplexVector c) {
  constexpr double kInfinite = 1e8;
  double t = 0;
  double step = 0.01;
  int successes = 0;
  for (int iteration = 0; iteration < 20'000 && t < 1; ++iteration) {
    if (c.norm() > kInfinite) return {PathEnd::Infinite, c};
    const double h = std::min(step, 1 - t);
    const auto k1 = homotopy.tangent(c, t);
    const auto k2 = k1 ? homotopy.tangent(c + 0.5 * h * *k1, t + 0.5 * h) : std::nullopt;
    const auto k3 = k2 ? homotopy.tangent(c + 0.5 * h * *k2, t + 0.5 * h) : std::nullopt;
    const auto k4 = k3 ? homotopy.tangent(c + h * *k3, t + h) : std::nullopt;
    bool accepted = false;
    ComplexVector next;
    if (k4) {
      next = c + h / 6 * (*k1 + 2 * *k2 + 2 * *k3 + *k4);
      const double scale = 1 + next.norm();
      double previous = std::numeric_limits<double>::infinity();
      for (int newton = 0; newton < 4; ++newton) {
        thread_local ComplexVector value;
        thread_local ComplexMatrix jacobian;
        thread_local Eigen::PartialPivLU<ComplexMatrix> lu;
        homotopy.evaluate(next, t + h, value, jacobian, nullptr);
        const ComplexVector delta = lu.compute(jacobian).solve(value);
        if (!delta.allFinite()) break;
        const double size = delta.norm();
        // the first correction must be small against the point and each next one contract
        if (size > 0.05 * scale || (newton > 0 && size > 0.5 * previous)) break;
        next -= delta;
        previous = size;
        if (size < 1e-11 * scale) {
          accepted = true;
          break;
        }
      }
    }
    if (accepted) {
      c = next;
      t += h;
      if (++successes >= 3) {
        step = std::min(0.1, step * 2);
        successes = 0;
      }
    } else {
      step /= 2;
      successes = 0;
      if (step < 1e-13) {
        if (c.norm() > 1e4) return {PathEnd::Infinite, c};
        // the last steps into a multiple root, where Newton no longer contracts fast: its end
        // is good to about the square root of the rounding, which search() and polish() allow
        if (t > 1 - 1e-4) return {PathEnd::Finite, c};
        return {PathEnd::Failed, c};
      }
    }
  }
  if (t < 1) return {PathEnd::Failed, c};
  return {c.norm() > kInfinite ? PathEnd::Infinite : PathEnd::Finite, c};
}

// A real root of F polished in binary128 (Newton from `c`: a path's end, or a double design's
// compliances), F's numbers in R (double, or binary128 for a chain given in it).
template <typename R>
std::optional<std::vector<Quad>> polish(const BasicScaled<R>& scaled, std::vector<Quad> c) {
  const std::size_t n = scaled.masses.size();
  using QuadVector = Eigen::Matrix<Quad, Eigen::Dynamic, 1>;
  using QuadMatrix = Eigen::Matrix<Quad, Eigen::Dynamic, Eigen::Dynamic>;
  // quadratic at a simple root; at a double one (a design at the edge of existing) each step
  // only halves the error: room for that
  for (int iteration = 0; iteration < 80; ++iteration) {
    QuadVector value;
    QuadMatrix jacobian;
    target(scaled, c, value, &jacobian);
    const QuadVector delta = Eigen::PartialPivLU<QuadMatrix>(jacobian).solve(value);
    Quad size = 0;
    for (std::size_t i = 0; i < n; ++i) {
      c[i] -= delta[Eigen::Index(i)];
      size = std::max(size, Quad(fabs(delta[Eigen::Index(i)]) / (1 + fabs(c[i]))));
    }
    if (!(size == size)) return std::nullopt;
    if (size < Quad(1e-32)) return c;
  }
  return c;  // what Newton reached: the spectrum check below decides
}

// F's Jacobian is singular at c within what a path's end resolves (a multiple root's end is
// only good to about the square root of the rounding)
bool singularAt(const Scaled& scaled, const ComplexVector& c) {
  ComplexVector value;
  ComplexMatrix jacobian;
  target(scaled, std::vector<Complex>(c.data(), c.data() + c.size()), value, &jacobian);
  const Eigen::JacobiSVD<ComplexMatrix> svd(jacobian);
  const Eigen::VectorXd sigma = svd.singularValues();
  return sigma[sigma.size() - 1] < 1e-5 * sigma[0];
}

// A finite end of the paths: a root of F, simple or reached by several paths.
struct Root {
  ComplexVector c;
  bool multiple = false;
};

struct SearchResult {
  bool complete = false;
  bool stopped = false;
  std::vector<Root> finite;
  int infinite = 0;
  int paths = 0;
};

// Every path of one homotopy; complete when each reached t = 1 and no two finite ends meet.
SearchResult search(const Scaled& scaled, std::uint64_t seed, const std::stop_token& stop) {
  const Eigen::Index n = Eigen::Index(scaled.masses.size());
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  std::uniform_real_distribution<double> radius(0.5, 1.5);
  StartSystem start;
  start.r.resize(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) start.r(i, j) = std::polar(radius(random), angle(random));
  }
  if (scaled.rightRatio > 0) {
    start.q.resize(n);
    for (Eigen::Index j = 0; j < n; ++j) start.q[j] = std::polar(radius(random), angle(random));
  }
  const Homotopy homotopy{scaled, start, std::polar(1.0, angle(random))};
  SearchResult result;
  std::vector<Eigen::Index> permutation(static_cast<std::size_t>(n));
  std::iota(permutation.begin(), permutation.end(), 0);
  do {
    if (stop.stop_requested()) {
      result.stopped = true;
      return result;
    }
    for (int second = 0; second < (start.q.size() ? 2 : 1); ++second) {
      ComplexVector c(n);
      for (Eigen::Index j = 0; j < n; ++j) {
        const Eigen::Index i = permutation[std::size_t(j)];
        c[i] = i == 0 && second ? start.q[j] : start.r(i, j);
      }
      ++result.paths;
      const TrackedPath path = track(homotopy, c);
      if (path.end == PathEnd::Failed) return result;
      if (path.end == PathEnd::Infinite) {
        ++result.infinite;
        continue;
      }
      bool repeated = false;
      for (Root& other : result.finite) {
        if ((other.c - path.c).norm() > 1e-4 * (1 + path.c.norm())) continue;
        // two paths at one end: a multiple root (the two designs of N = 2, 1:2 meet at
        // m2/m1 = 9/16), where F's Jacobian is singular; at a regular root one of them jumped,
        // and some solution may have been missed
        if (!singularAt(scaled, path.c)) return result;
        other.multiple = repeated = true;
      }
      if (!repeated) result.finite.push_back({path.c, false});
    }
  } while (std::next_permutation(permutation.begin(), permutation.end()));
  result.complete = true;
  return result;
}

}  // namespace

ChainDesigns designSprings(const std::vector<double>& masses, double k1, const std::vector<int>& harmonics,
                           std::stop_token stop) {
  return designSprings(masses, k1, 0, harmonics, stop);
}

ChainDesigns designSprings(const std::vector<double>& masses, double k1, double rightSpring,
                           const std::vector<int>& harmonics, std::stop_token stop) {
  ChainDesigns designs;
  const std::size_t n = masses.size();
  const bool usable =
      n >= 1 && n <= std::size_t(kMaxDesignMasses) && harmonics.size() == n && k1 > 0 && std::isfinite(k1) &&
      rightSpring >= 0 && std::isfinite(rightSpring) && (rightSpring == 0 || k1 / rightSpring < 1e300) &&
      std::all_of(masses.begin(), masses.end(), [](double m) { return m > 0 && std::isfinite(m); }) &&
      std::all_of(harmonics.begin(), harmonics.end(), [](int h) { return h >= 1; }) &&
      std::adjacent_find(harmonics.begin(), harmonics.end(), [](int a, int b) { return a <= b; }) == harmonics.end();
  if (!usable) return designs;
  // n_j over their gcd: w0 is then the chain's own base frequency (T the least common period)
  int divisor = 0;
  for (int h : harmonics) divisor = std::gcd(divisor, h);
  std::vector<int> reduced(harmonics);
  for (int& h : reduced) h /= divisor;

  Scaled scaled;
  const double heaviest = *std::max_element(masses.begin(), masses.end());
  const double fastest = double(reduced.front());
  for (double m : masses) scaled.masses.push_back(m / heaviest);
  for (int h : reduced) scaled.lambdas.push_back(double(h) * h / (fastest * fastest));
  if (rightSpring > 0) scaled.rightRatio = k1 / rightSpring;

  std::optional<SearchResult> found;
  for (std::uint64_t attempt = 0; attempt < 4 && !found; ++attempt) {
    SearchResult result = search(scaled, 0x9e3779b97f4a7c15ULL + attempt, stop);
    if (result.stopped) {
      designs.outcome = DesignOutcome::Stopped;
      return designs;
    }
    if (result.complete) found = std::move(result);
  }
  if (!found) {
    designs.outcome = DesignOutcome::Incomplete;
    return designs;
  }
  designs.paths = found->paths;
  designs.infiniteEnds = found->infinite;
  for (const Root& root : found->finite) {
    const ComplexVector& end = root.c;
    const double scale = 1 + end.norm();
    // a multiple root's end is good to about the square root of the rounding only
    const bool real = (end.imag().array().abs() < (root.multiple ? 1e-4 : 1e-8) * scale).all();
    if (!real || !(end.real().array() > 0).all()) {
      ++designs.complexEnds;
      continue;
    }
    std::vector<Quad> start(n);
    for (std::size_t i = 0; i < n; ++i) start[i] = Quad(end[Eigen::Index(i)].real());
    const std::optional<std::vector<Quad>> c = polish(scaled, std::move(start));
    if (!c || !std::all_of(c->begin(), c->end(), [](const Quad& x) { return x > 0; })) {
      ++designs.complexEnds;
      continue;
    }
    // k_i = s / c_i with s = k1 c_1 (so k_1 is as asked); the eigenvalues of M^-1 K are then
    // (s / m_max) n_j^2 / n_max^2
    const Quad s = Quad(k1) * (*c)[0];
    ChainDesign design;
    for (std::size_t i = 0; i < n; ++i) design.springs.push_back(i == 0 ? k1 : double(s / (*c)[i]));
    design.omega0 = double(sqrt(s / Quad(heaviest)) / Quad(fastest));
    // the designed chain's own spectrum, in binary128: the design stands only if it checks
    const ChainModes modes = chainModes(MassChain{masses, design.springs, rightSpring, 0, 1});
    for (std::size_t j = 0; j < n; ++j) {
      const double wanted = reduced[j] * design.omega0;
      design.ratioError = std::max(design.ratioError, std::abs(modes.omega[Eigen::Index(j)] / wanted - 1));
    }
    if (!(design.ratioError <= 1e-13) && root.multiple) {
      // a pair of complex roots a hair apart (just past the edge of existing), not a real one
      ++designs.complexEnds;
      continue;
    }
    if (!(design.ratioError <= 1e-13)) {
      // a simple root the spectrum does not confirm: no list can be promised
      designs.outcome = DesignOutcome::Incomplete;
      designs.designs.clear();
      return designs;
    }
    designs.designs.push_back(design);
  }
  std::sort(designs.designs.begin(), designs.designs.end(), [](const ChainDesign& a, const ChainDesign& b) {
    return std::lexicographical_compare(b.springs.begin() + 1, b.springs.end(), a.springs.begin() + 1, a.springs.end());
  });
  designs.outcome = designs.designs.empty() ? DesignOutcome::NoPositiveDesign : DesignOutcome::Designed;
  return designs;
}

std::optional<std::vector<Quad>> refinedSprings(const std::vector<Quad>& masses, const Quad& k1,
                                                const Quad& rightSpring, const std::vector<int>& harmonics,
                                                const ChainDesign& design) {
  const std::size_t n = masses.size();
  if (n == 0 || harmonics.size() != n || design.springs.size() != n || !(design.omega0 > 0)) return std::nullopt;
  int divisor = 0;
  for (int h : harmonics) divisor = std::gcd(divisor, h);
  const Quad fastest = Quad(harmonics.front() / divisor);
  BasicScaled<Quad> scaled;
  const Quad heaviest = *std::max_element(masses.begin(), masses.end());
  for (const Quad& m : masses) scaled.masses.push_back(m / heaviest);
  for (int h : harmonics) scaled.lambdas.push_back(Quad(h / divisor) * Quad(h / divisor) / (fastest * fastest));
  if (rightSpring > 0) scaled.rightRatio = k1 / rightSpring;
  // the design's compliances in the scaled problem: k_i = s / c_i with s = w0^2 m_max n_max^2
  const Quad s = Quad(design.omega0) * Quad(design.omega0) * heaviest * fastest * fastest;
  std::vector<Quad> c(n);
  for (std::size_t i = 0; i < n; ++i) c[i] = s / Quad(design.springs[i]);
  const std::optional<std::vector<Quad>> root = polish(scaled, c);
  if (!root) return std::nullopt;
  std::vector<Quad> springs(n);
  const Quad scale = k1 * (*root)[0];
  for (std::size_t i = 0; i < n; ++i) {
    // the same design, only sharper: Newton stays near where it began (within double's error,
    // or its square root for a design where two meet)
    if (!((*root)[i] > 0) || !(fabs((*root)[i] / c[i] - 1) < Quad(1e-6))) return std::nullopt;
    springs[i] = i == 0 ? k1 : scale / (*root)[i];
  }
  // polish() returns what Newton reached after its iterations: the refined chain stands only if
  // its own binary128 spectrum is in the ratio to binary128's rounding (a chain just past the
  // edge where two designs meet has no real root near the double one, and Newton stalls there)
  const BasicChainModes<Quad> modes = chainModesIn<Quad>(BasicMassChain<Quad>{masses, springs, rightSpring, 0, Quad(1)});
  Quad dot = 0, norm = 0;
  for (std::size_t j = 0; j < n; ++j) {
    dot += Quad(harmonics[j]) * modes.omega[Eigen::Index(j)];
    norm += Quad(harmonics[j]) * Quad(harmonics[j]);
  }
  const Quad omega0 = dot / norm;
  for (std::size_t j = 0; j < n; ++j) {
    if (!(fabs(modes.omega[Eigen::Index(j)] / (Quad(harmonics[j]) * omega0) - 1) < Quad(1e-28))) return std::nullopt;
  }
  return springs;
}

namespace {

// The designs of the chains designed last, by their numbers: a design is a function of them
// alone, and an explorer's slider that moves the gap or the start (the chain's masses kept)
// would otherwise follow the same N! paths again at every step (3 masses: ~3 ms of a 30 ms
// frame). Only searches are kept: not a stopped one, nor a request refused before any search
// (it costs nothing to refuse again, and would push a design out).
struct DesignKey {
  std::vector<double> masses;
  double k1;
  double rightSpring;
  std::vector<int> harmonics;
  bool operator==(const DesignKey&) const = default;
};

ChainDesigns recentDesigns(const std::vector<double>& masses, double k1, double rightSpring,
                           const std::vector<int>& harmonics, std::stop_token stop) {
  static std::mutex mutex;
  static std::deque<std::pair<DesignKey, ChainDesigns>> recent;  // the latest last
  constexpr std::size_t kKept = 8;
  DesignKey key{masses, k1, rightSpring, harmonics};
  {
    const std::lock_guard lock(mutex);
    const auto found = std::find_if(recent.begin(), recent.end(), [&key](const auto& kept) { return kept.first == key; });
    if (found != recent.end()) return found->second;
  }
  ChainDesigns designs = designSprings(masses, k1, rightSpring, harmonics, std::move(stop));
  if (designs.outcome != DesignOutcome::Stopped && designs.outcome != DesignOutcome::BadRequest) {
    const std::lock_guard lock(mutex);
    recent.emplace_back(std::move(key), designs);
    if (recent.size() > kKept) recent.pop_front();
  }
  return designs;
}

}  // namespace

DesignChoice chooseDesign(const std::vector<double>& masses, double k1, double rightSpring,
                          const std::vector<int>& harmonics, int number, std::stop_token stop) {
  DesignChoice choice{harmonics, recentDesigns(masses, k1, rightSpring, harmonics, std::move(stop)), number,
                      DesignChoiceProblem::None};
  switch (choice.designs.outcome) {
    case DesignOutcome::Designed:
      if (number < 1 || number > int(choice.designs.designs.size())) choice.problem = DesignChoiceProblem::NoSuchDesign;
      break;
    case DesignOutcome::NoPositiveDesign: choice.problem = DesignChoiceProblem::NoPositiveDesign; break;
    case DesignOutcome::Incomplete: choice.problem = DesignChoiceProblem::Incomplete; break;
    case DesignOutcome::Stopped: choice.problem = DesignChoiceProblem::Stopped; break;
    case DesignOutcome::BadRequest: choice.problem = DesignChoiceProblem::BadRequest; break;
  }
  return choice;
}

template <typename S>
std::optional<std::vector<S>> designedSpringsIn(const std::vector<S>& masses, const S& k1, const S& rightSpring,
                                                const DesignChoice& choice) {
  if (choice.problem != DesignChoiceProblem::None) return std::nullopt;
  if constexpr (std::is_same_v<S, double>) {
    return choice.chosen().springs;
  } else {
    std::vector<Quad> wide;
    for (const S& m : masses) wide.push_back(Quad(m));
    const auto refined = refinedSprings(wide, Quad(k1), Quad(rightSpring), choice.harmonics, choice.chosen());
    if (!refined) return std::nullopt;
    std::vector<S> springs;
    for (const Quad& k : *refined) springs.push_back(static_cast<S>(k));
    return springs;
  }
}

template std::optional<std::vector<double>> designedSpringsIn<double>(const std::vector<double>&, const double&,
                                                                      const double&, const DesignChoice&);
template std::optional<std::vector<long double>> designedSpringsIn<long double>(const std::vector<long double>&,
                                                                                const long double&,
                                                                                const long double&,
                                                                                const DesignChoice&);
template std::optional<std::vector<Quad>> designedSpringsIn<Quad>(const std::vector<Quad>&, const Quad&, const Quad&,
                                                                  const DesignChoice&);

}  // namespace grazelab::core
