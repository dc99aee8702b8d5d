// gradcontact: the command line of the suite (the commands live in the library, cases/app/command_line.h).
//
//   gradcontact eval [file]                  JSON Lines requests (stdin without file) -> one answer a line
//   gradcontact run <scene|folder> ...       run scenes, write reports/<scene>/ and reports/summary.md
//   gradcontact sweep <scene.prm> --over Section/key=v1,v2,...
//                                            run a scene once per value
//   gradcontact figures <file.json|folder>   draw the chapter's figures -> reports/figures/
//   gradcontact bench                        work-precision benchmarks -> reports/benchmarks/
//   gradcontact stress                       numerical-stability tables -> reports/benchmarks/stability.md
//   gradcontact --help                       every command;  gradcontact <command> --help: one command
//
// Sample runs:
//   echo '{"id":1,"case":"paraboloid","quantity":"force","material":{"E0":1e9,"c0":1e-3,"k":0.5,
//          "nu":0.3},"geometry":{"R":0.01},"a":1e-4}' | gradcontact eval
//   gradcontact run cases/default
//
// Errors are reported here, at the boundary: what() on stderr and a non-zero exit code. MPI starts here when
// an MPI launcher started the process, else only when a scene of the distributed 3D model needs it
// (cases/model/mpi_session.h: starting it costs a singleton process more than a short FE run).
#include "app/command_line.h"

#ifndef GRADCONTACT_WITH_FEM
#  define GRADCONTACT_WITH_FEM 1 // the FE build; cases/CMakeLists.txt sets 0 for -DGRADCONTACT_WITH_FEM=OFF
#endif
#if GRADCONTACT_WITH_FEM
#  include "model/mpi_session.h"
#endif

#include <exception>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char **argv)
{
  try
    {
#if GRADCONTACT_WITH_FEM
      gradcontact::cases::MpiSession mpi(argc, argv);
#endif
      return gradcontact::cases::command_line(std::vector<std::string>(argv + 1, argv + argc), std::cout);
    }
  catch (const std::exception &e)
    {
      std::cerr << "gradcontact: " << e.what() << '\n';
      return 1;
    }
}
