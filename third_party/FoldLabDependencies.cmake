# Imported targets for the Debian 12 system packages FoldLab uses. Nothing here is downloaded:
# scripts/install-deps.sh installs the packages, this file only finds them.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(Threads REQUIRED)
