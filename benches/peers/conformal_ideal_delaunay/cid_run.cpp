// Benchmark driver for ConformalIdealDelaunay (Campen, Capouellez, Shen, Zhu, Panozzo,
// Zorin 2021), double precision. Written for penner's peer benchmarks; it only calls the
// peer's public C++ interface (ConformalInterface.hh) with the parameters that
// py/script_conformal.py sets for a double run, so that the whole process can be timed
// without the Python/pybind layer.
//
//   cid_run MESH.obj MESH_Th_hat [--overlay] [--eps E] [--max-itr N] [-o OUT]
//
// Default (no --overlay): conformal_metric<double> with bypass_overlay = true, as the
// paper's efficiency scripts run it (figures/compare_efficiency: --max_itr 50
// --bypass_overlay, eps 0); writes the scale factors u (one per vertex of the peer's
// reindexed mesh) to OUT.
// --overlay: conformal_parametrization_VL<double> (overlay mesh + layout), the script's
// `--output_type param --output_format obj`; writes the overlay mesh with its UVs to OUT.
#include "ConformalInterface.hh"
#include <igl/readOBJ.h>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: cid_run MESH.obj TH_HAT [--overlay] [--eps E] [--max-itr N] [-o OUT]\n";
    return 2;
  }
  std::string mesh = argv[1], th = argv[2], out = "cid_out.txt";
  bool overlay = false;
  double eps = 0;
  int max_itr = 50;  // script_conformal.py's default
  for (int i = 3; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--overlay") overlay = true;
    else if (a == "--eps" && i + 1 < argc) eps = std::stod(argv[++i]);
    else if (a == "--max-itr" && i + 1 < argc) max_itr = std::stoi(argv[++i]);
    else if (a == "-o" && i + 1 < argc) out = argv[++i];
    else { std::cerr << "unknown argument " << a << "\n"; return 2; }
  }
  auto t0 = std::chrono::steady_clock::now();
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  if (!igl::readOBJ(mesh, V, F)) { std::cerr << "cannot read " << mesh << "\n"; return 1; }
  std::vector<double> Th_hat;
  {
    std::ifstream f(th);
    double x;
    while (f >> x) Th_hat.push_back(x);
  }
  if ((long)Th_hat.size() != V.rows()) {
    std::cerr << "Th_hat has " << Th_hat.size() << " values, mesh " << V.rows() << " vertices\n";
    return 1;
  }
  auto t1 = std::chrono::steady_clock::now();

  auto alg = std::make_shared<AlgorithmParameters>();
  alg->initial_ptolemy = false;
  alg->error_eps = eps;
  alg->min_lambda = 1e-16;
  alg->newton_decr_thres = -0.01 * eps * eps;
  alg->max_itr = max_itr;
  alg->bypass_overlay = !overlay;
  auto ls = std::make_shared<LineSearchParameters>();
  ls->energy_cond = false;
  ls->energy_samples = false;
  ls->do_reduction = false;
  ls->do_grad_norm_decrease = true;
  ls->bound_norm_thres = 1e-10;
  ls->lambda0 = 1;
  ls->reset_lambda = true;
  auto stats = std::make_shared<StatsParameters>();
  stats->log_level = 2;

  if (!overlay) {
    std::vector<int> pt_fids;
    std::vector<Eigen::Matrix<double, 3, 1>> pt_bcs;
    auto res = conformal_metric<double>(V, F, Th_hat, pt_fids, pt_bcs, alg, ls, stats);
    const std::vector<double>& u = std::get<1>(res);
    auto t2 = std::chrono::steady_clock::now();
    FILE* fo = std::fopen(out.c_str(), "w");
    for (double x : u) std::fprintf(fo, "%.17g\n", x);
    std::fclose(fo);
    auto t3 = std::chrono::steady_clock::now();
    std::fprintf(stderr, "cid_run: read %.3f s, conformal_metric %.3f s, write %.3f s, %zu u\n",
                 std::chrono::duration<double>(t1 - t0).count(),
                 std::chrono::duration<double>(t2 - t1).count(),
                 std::chrono::duration<double>(t3 - t2).count(), u.size());
  } else {
    auto res = conformal_parametrization_VL<double>(V, F, Th_hat, alg, ls, stats);
    auto& vo = std::get<0>(res);
    auto& fo_ = std::get<1>(res);
    auto& uu = std::get<2>(res);
    auto& vv = std::get<3>(res);
    auto& ft = std::get<4>(res);
    auto t2 = std::chrono::steady_clock::now();
    FILE* fo = std::fopen(out.c_str(), "w");
    for (auto& p : vo) std::fprintf(fo, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
    for (size_t i = 0; i < uu.size(); ++i) std::fprintf(fo, "vt %.17g %.17g\n", uu[i], vv[i]);
    for (size_t i = 0; i < fo_.size(); ++i)
      std::fprintf(fo, "f %d/%d %d/%d %d/%d\n", fo_[i][0] + 1, ft[i][0] + 1, fo_[i][1] + 1,
                   ft[i][1] + 1, fo_[i][2] + 1, ft[i][2] + 1);
    std::fclose(fo);
    auto t3 = std::chrono::steady_clock::now();
    std::fprintf(stderr, "cid_run: read %.3f s, conformal_parametrization_VL %.3f s, write %.3f s, %zu faces\n",
                 std::chrono::duration<double>(t1 - t0).count(),
                 std::chrono::duration<double>(t2 - t1).count(),
                 std::chrono::duration<double>(t3 - t2).count(), fo_.size());
  }
  return 0;
}
