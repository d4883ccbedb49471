#include "csdp_backend.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <mutex>
#include <new>
#include <string>
#include <tuple>
#include <vector>

extern "C" {
#include <csdp/declarations.h>
}

#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"

namespace vantage::sdp::internal {
namespace {

// CSDP's own defaults (its initparams()), written out here because initparams() reads
// param.csdp from the working directory.
// CSDP is not reentrant: op_o() keeps its work matrices in a function-level static pointer, which
// every call allocates, uses and frees. Two solves at once read each other's buffers and free them
// twice (the process aborts), so the solver loop runs under one process-wide lock; building the
// problem and reading the answer stay outside it.
std::mutex& csdp_mutex() {
  static std::mutex mutex;
  return mutex;
}

paramstruc csdp_parameters(const SdpOptions& options) {
  paramstruc p;
  p.axtol = options.tolerance;
  p.atytol = options.tolerance;
  p.objtol = options.tolerance;
  p.pinftol = 1.0e8;
  p.dinftol = 1.0e8;
  p.maxiter = options.max_iterations;
  p.minstepfrac = 0.90;
  p.maxstepfrac = 0.97;
  p.minstepp = 1.0e-8;
  p.minstepd = 1.0e-8;
  p.usexzgap = 1;
  p.tweakgap = 0;
  p.affine = 0;
  p.perturbobj = 1;
  p.fastmode = 0;
  return p;
}

template <typename T>
T* c_alloc(size_t count) {
  void* memory = std::calloc(count, sizeof(T));
  if (memory == nullptr) throw std::bad_alloc();
  return static_cast<T*>(memory);
}

const char* message_for(int code) {
  switch (code) {
    case 0:
      return "CSDP: problem solved";
    case 1:
      return "CSDP: certificate of (CSDP-)primal infeasibility: the LMI objective is unbounded";
    case 2:
      return "CSDP: certificate of (CSDP-)dual infeasibility: the LMI is infeasible";
    case 3:
      return "CSDP: solved with reduced accuracy";
    case 4:
      return "CSDP: maximum iterations reached";
    case 5:
      return "CSDP: stuck at edge of primal feasibility";
    case 6:
      return "CSDP: stuck at edge of dual feasibility";
    case 7:
      return "CSDP: lack of progress";
    case 8:
      return "CSDP: X, Z or O was singular";
    case 9:
      return "CSDP: detected NaN or Inf values";
    default:
      return "CSDP: error return code";
  }
}

// Owns every CSDP allocation of one solve; the destructor releases them in CSDP's own way
// (free_prob for the problem and solution, free_mat / free_mat_packed for work matrices).
struct CsdpSolve {
  int n = 0;
  int k = 0;
  blockmatrix C{0, nullptr};
  double* a = nullptr;
  constraintmatrix* constraints = nullptr;
  blockmatrix X{0, nullptr};
  blockmatrix Z{0, nullptr};
  double* y = nullptr;
  bool have_solution = false;
  constraintmatrix fill{nullptr};
  blockmatrix work1{0, nullptr}, work2{0, nullptr}, work3{0, nullptr};
  blockmatrix bestx{0, nullptr}, bestz{0, nullptr}, cholxinv{0, nullptr}, cholzinv{0, nullptr};
  blockmatrix Zi{0, nullptr}, dZ{0, nullptr}, dX{0, nullptr};

  CsdpSolve() = default;
  CsdpSolve(const CsdpSolve&) = delete;
  CsdpSolve& operator=(const CsdpSolve&) = delete;

  ~CsdpSolve() {
    for (blockmatrix* m : {&work1, &work2, &work3, &Zi, &dZ, &dX}) {
      if (m->blocks != nullptr) free_mat(*m);
    }
    for (blockmatrix* m : {&bestx, &bestz, &cholxinv, &cholzinv}) {
      if (m->blocks != nullptr) free_mat_packed(*m);
    }
    sparseblock* p = fill.blocks;
    while (p != nullptr) {
      sparseblock* next = p->next;
      std::free(p->entries);
      std::free(p->iindices);
      std::free(p->jindices);
      std::free(p);
      p = next;
    }
    if (have_solution) {
      free_prob(n, k, C, a, constraints, X, y, Z);
      return;
    }
    // Before initsoln() the solution does not exist: release the problem by hand.
    if (constraints != nullptr) {
      for (int j = 1; j <= k; ++j) {
        sparseblock* q = constraints[j].blocks;
        while (q != nullptr) {
          sparseblock* next = q->next;
          std::free(q->entries);
          std::free(q->iindices);
          std::free(q->jindices);
          std::free(q);
          q = next;
        }
      }
      std::free(constraints);
    }
    if (C.blocks != nullptr) {
      for (int b = 1; b <= C.nblocks; ++b) std::free(C.blocks[b].data.vec);
      std::free(C.blocks);
    }
    std::free(a);
  }
};

}  // namespace

SdpStatus status_from_csdp_code(int code) {
  switch (code) {
    case 0:
      return SdpStatus::kOptimal;
    case 1:
      return SdpStatus::kUnbounded;
    case 2:
      return SdpStatus::kInfeasible;
    case 3:
      return SdpStatus::kOptimalReducedAccuracy;
    case 4:
      return SdpStatus::kMaxIterations;
    case 5:
      return SdpStatus::kStuckPrimal;
    case 6:
      return SdpStatus::kStuckDual;
    case 7:
      return SdpStatus::kNoProgress;
    case 8:
      return SdpStatus::kSingular;
    case 9:
      return SdpStatus::kNumericalError;
    default:
      return SdpStatus::kBackendError;
  }
}

namespace {

using EntryKey = std::tuple<int, int, int, int>;  // (matrix, block, row, col), 0-based
using BlockEntries = std::vector<std::tuple<int, int, double>>;  // (row, col, value), 1-based

// Sums duplicate entries of the problem by (matrix, block, row, col).
std::map<EntryKey, double> summed_entries(const LmiProblem& problem) {
  std::map<EntryKey, double> summed;
  for (const LmiProblem::Entry& e : problem.entries()) {
    summed[{e.matrix, e.block, e.row, e.col}] += e.value;
  }
  return summed;
}

// Allocates C = F_0's blocks (CSDP indexing: blocks 1..nblocks, vectors 1..size, matrices
// column-major), all zero, and the objective vector a.
void allocate_objective(const LmiProblem& problem, CsdpSolve& s) {
  const int num_blocks = problem.num_blocks();
  s.C.nblocks = num_blocks;
  s.C.blocks = c_alloc<blockrec>(num_blocks + 1);
  for (int b = 0; b < num_blocks; ++b) {
    blockrec& rec = s.C.blocks[b + 1];
    const int size = problem.block_size(b);
    rec.blocksize = size;
    if (problem.block_kind(b) == BlockKind::kDiagonal) {
      rec.blockcategory = DIAG;
      rec.data.vec = c_alloc<double>(size + 1);
    } else {
      rec.blockcategory = MATRIX;
      rec.data.mat = c_alloc<double>(static_cast<size_t>(size) * size);
    }
  }
  s.a = c_alloc<double>(s.k + 1);
  for (int j = 0; j < s.k; ++j) s.a[j + 1] = problem.objective()(j);
}

// Fills C with F_0's entries and returns the constraint entries grouped by (constraint, block).
std::map<std::pair<int, int>, BlockEntries> fill_objective_and_group(
    const std::map<EntryKey, double>& summed, CsdpSolve& s) {
  std::map<std::pair<int, int>, BlockEntries> grouped;
  for (const auto& [key, value] : summed) {
    const auto [matrix, block, row, col] = key;
    if (value == 0.0) continue;
    if (matrix == 0) {
      blockrec& rec = s.C.blocks[block + 1];
      if (rec.blockcategory == DIAG) {
        rec.data.vec[row + 1] = value;
      } else {
        rec.data.mat[ijtok(row + 1, col + 1, rec.blocksize)] = value;
        rec.data.mat[ijtok(col + 1, row + 1, rec.blocksize)] = value;
      }
    } else {
      grouped[{matrix, block}].emplace_back(row + 1, col + 1, value);
    }
  }
  return grouped;
}

// Builds CSDP's sparse constraint blocks F_1..F_k, each constraint's blocks in block order.
void build_constraints(const LmiProblem& problem,
                       const std::map<std::pair<int, int>, BlockEntries>& grouped, CsdpSolve& s) {
  s.constraints = c_alloc<constraintmatrix>(s.k + 1);
  std::vector<sparseblock*> tail(s.k + 1, nullptr);
  for (const auto& [key, list] : grouped) {  // ordered by constraint, then by block
    const auto [matrix, block] = key;
    auto* sb = c_alloc<sparseblock>(1);
    const int count = static_cast<int>(list.size());
    sb->numentries = count;
    sb->blocknum = block + 1;
    sb->blocksize = problem.block_size(block);
    sb->constraintnum = matrix;
    sb->entries = c_alloc<double>(count + 1);
    sb->iindices = c_alloc<int>(count + 1);
    sb->jindices = c_alloc<int>(count + 1);
    for (int e = 0; e < count; ++e) {
      sb->iindices[e + 1] = std::get<0>(list[e]);
      sb->jindices[e + 1] = std::get<1>(list[e]);
      sb->entries[e + 1] = std::get<2>(list[e]);
    }
    const bool diagonal = problem.block_kind(block) == BlockKind::kDiagonal;
    sb->issparse = (diagonal || 4 * count < sb->blocksize * sb->blocksize) ? 1 : 0;
    if (tail[matrix] == nullptr) {
      s.constraints[matrix].blocks = sb;
    } else {
      tail[matrix]->next = sb;
    }
    tail[matrix] = sb;
  }
  for (int j = 1; j <= s.k; ++j) {
    if (s.constraints[j].blocks == nullptr) {
      vantage::internal::fail("problem", "F_" + std::to_string(j) + " sums to zero");
    }
  }
}

// Cross links of the blocks of equal block number, in constraint order (CSDP's byblocks).
std::vector<sparseblock*> link_by_blocks(int num_blocks, const CsdpSolve& s) {
  std::vector<sparseblock*> byblocks(num_blocks + 1, nullptr);
  std::vector<sparseblock*> last_in_block(num_blocks + 1, nullptr);
  for (int j = 1; j <= s.k; ++j) {
    for (sparseblock* p = s.constraints[j].blocks; p != nullptr; p = p->next) {
      p->nextbyblock = nullptr;
      if (last_in_block[p->blocknum] == nullptr) {
        byblocks[p->blocknum] = p;
      } else {
        last_in_block[p->blocknum]->nextbyblock = p;
      }
      last_in_block[p->blocknum] = p;
    }
  }
  return byblocks;
}

// Allocates the work matrices and the initial solution, runs CSDP's sdp() under the process-wide
// lock and returns its code; the objectives go to *pobj and *dobj.
int run_csdp(const SdpOptions& options, std::vector<sparseblock*>& byblocks, CsdpSolve& s,
             double* pobj, double* dobj) {
  const int printlevel = 0;
  alloc_mat(s.C, &s.work1);
  alloc_mat(s.C, &s.work2);
  alloc_mat(s.C, &s.work3);
  alloc_mat_packed(s.C, &s.bestx);
  alloc_mat_packed(s.C, &s.bestz);
  alloc_mat_packed(s.C, &s.cholxinv);
  alloc_mat_packed(s.C, &s.cholzinv);
  alloc_mat(s.C, &s.Zi);
  alloc_mat(s.C, &s.dZ);
  alloc_mat(s.C, &s.dX);

  sort_entries(s.k, s.C, s.constraints);
  makefill(s.k, s.C, s.constraints, &s.fill, s.work1, printlevel);
  initsoln(s.n, s.k, s.C, s.a, s.constraints, &s.X, &s.y, &s.Z);
  s.have_solution = true;

  const size_t nk = static_cast<size_t>(std::max(s.n, s.k)) + 1;
  std::vector<std::vector<double>> workvec(8, std::vector<double>(nk, 0.0));
  std::vector<double> diag_o(nk, 0.0);
  std::vector<double> besty(s.k + 1, 0.0), rhs(s.k + 1, 0.0), dy(s.k + 1, 0.0), dy1(s.k + 1, 0.0),
      fp(s.k + 1, 0.0);
  const size_t ldam = static_cast<size_t>(s.k % 2 == 0 ? s.k + 1 : s.k);
  std::vector<double> O(ldam * ldam, 0.0);

  std::unique_lock<std::mutex> lock(csdp_mutex());
  const int code = ::sdp(
      s.n, s.k, s.C, s.a, 0.0, s.constraints, byblocks.data(), s.fill, s.X, s.y, s.Z, s.cholxinv,
      s.cholzinv, pobj, dobj, s.work1, s.work2, s.work3, workvec[0].data(), workvec[1].data(),
      workvec[2].data(), workvec[3].data(), workvec[4].data(), workvec[5].data(), workvec[6].data(),
      workvec[7].data(), diag_o.data(), s.bestx, besty.data(), s.bestz, s.Zi, O.data(), rhs.data(),
      s.dZ, s.dX, dy.data(), dy1.data(), fp.data(), printlevel, csdp_parameters(options));
  lock.unlock();
  return code;
}

}  // namespace

SdpResult solve_with_csdp(const LmiProblem& problem, const SdpOptions& options) {
  const int num_blocks = problem.num_blocks();
  CsdpSolve s;
  s.k = problem.num_variables();
  for (int b = 0; b < num_blocks; ++b) s.n += problem.block_size(b);

  const std::map<EntryKey, double> summed = summed_entries(problem);
  allocate_objective(problem, s);
  build_constraints(problem, fill_objective_and_group(summed, s), s);
  std::vector<sparseblock*> byblocks = link_by_blocks(num_blocks, s);

  double pobj = 0.0;
  double dobj = 0.0;
  const int code = run_csdp(options, byblocks, s, &pobj, &dobj);

  SdpResult result;
  result.status = status_from_csdp_code(code);
  result.backend = to_string(SdpBackend::kCsdp);
  result.message = message_for(code);
  if (code > 10 || code < 0) result.message += " " + std::to_string(code);
  result.y.resize(s.k);
  for (int j = 0; j < s.k; ++j) result.y(j) = s.y[j + 1];
  result.primal_objective = dobj;
  result.dual_objective = pobj;
  result.gap = dobj - pobj;
  return result;
}

}  // namespace vantage::sdp::internal
