/// @file thesis_signature_header_main.cpp
/// Writes the thesis firmware's hand-made fault-signature table (the test oracle's
/// generator, signature_table.hpp) to the file given, or to stdout:
///   thesis_signature_header lib/include/hstmon/generated/thesis_signatures.hpp
/// test_fdi_table fails while the committed header differs from what this writes.
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>

#include "hstmon_fdi/signature_table.hpp"

int main(int argc, char** argv) {
  using namespace hstmon::fdi;
  if (argc > 2) {
    std::cerr << "usage: thesis_signature_header [OUT]\n";
    return 2;
  }
  try {
    const SignatureOptions opt;
    const std::string text = render_signature_header(build_signature_rows(opt), opt);
    if (argc == 1) {
      std::cout << text;
      return 0;
    }
    std::ofstream f(argv[1], std::ios::binary);
    if (!(f << text)) {
      std::cerr << "thesis_signature_header: cannot write " << argv[1] << '\n';
      return 1;
    }
  } catch (const std::exception& e) {
    std::cerr << "thesis_signature_header: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
