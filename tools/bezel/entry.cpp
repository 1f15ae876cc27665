// The process entry point, alone in its file: everything else of the CLI is the bezel_cli_core
// library, which the fuzz replay (tests/fuzz) and the libFuzzer target link without a main().
namespace bezel::cli {
int run_cli(int argc, char** argv);  // main.cpp
}

int main(int argc, char** argv) { return bezel::cli::run_cli(argc, argv); }
