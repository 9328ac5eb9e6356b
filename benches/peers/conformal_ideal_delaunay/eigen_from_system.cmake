# Injected with -DCMAKE_PROJECT_INCLUDE: provides Eigen3::Eigen from the system (apt
# libeigen3-dev) before libigl's cmake/libigl.cmake runs, so libigl skips its
# igl_download_eigen() (which would clone from gitlab; no network here).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
