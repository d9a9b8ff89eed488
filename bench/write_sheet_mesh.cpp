// Writes the benchmarks' wavy sheet (tests/support/sheet_mesh.h) for scripts: write_sheet_mesh FILE.ply TRIANGLES

#include <cstdlib>
#include <iostream>

#include "sheet_mesh.h"

int main(int argc, char** argv)
{
    if (argc != 3 || std::atol(argv[2]) < 2) {
        std::cerr << "usage: write_sheet_mesh FILE.ply TRIANGLES (at least 2)\n";
        return 2;
    }
    viewpipe::bench::writeSheetMesh(argv[1], std::atol(argv[2]));
}
