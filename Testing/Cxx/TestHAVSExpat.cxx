/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSExpat.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// VTK's XML readers against the expat this machine has: a grid written with
// vtkXMLUnstructuredGridWriter (appended raw, appended base64, inline binary,
// ASCII) is read back with vtkXMLUnstructuredGridReader and compared.
//
//   TestHAVSExpat fixed    the program carries vtkHAVSExpatFix (or has it
//                          preloaded): every round trip must succeed.
//   TestHAVSExpat unfixed  the control, without the fix: where this expat has
//                          reparse deferral (Debian 12's 2.5.0-1+deb12u5,
//                          expat >= 2.6) the round trips must FAIL — the bug
//                          the fix is for is real here; where it has none, or
//                          where VTK (>= 9.3) turns the deferral off itself,
//                          they must succeed.
// Either way the program first says which expat it runs with.
#include "havsTestImages.h"

#include "vtkHAVSDataSets.h"

#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVersion.h"
#include "vtkXMLUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
/// The Debian package version of libexpat1, or "unknown".
std::string DebianExpatPackage()
{
  std::string version = "unknown";
  if (FILE* pipe = popen("dpkg-query -W -f='${Version}' libexpat1 2>/dev/null", "r"))
  {
    char buffer[128] = {};
    if (std::fgets(buffer, sizeof(buffer), pipe) && buffer[0])
    {
      version = buffer;
    }
    pclose(pipe);
  }
  return version;
}

std::string ExpatVersion()
{
  using VersionFunction = const char* (*)();
  auto f = reinterpret_cast<VersionFunction>(dlsym(RTLD_DEFAULT, "XML_ExpatVersion"));
  return f ? f() : "not loaded";
}

/// Parsers the fix turned the deferral off for; -1 when the fix is not in this process.
long FixedParsers()
{
  using CountFunction = unsigned long (*)();
  auto f = reinterpret_cast<CountFunction>(dlsym(RTLD_DEFAULT, "vtkHAVSExpatFixParserCount"));
  return f ? static_cast<long>(f()) : -1;
}

/// Writes `grid` in one encoding and reads it back; true when it is the same.
bool RoundTrip(vtkUnstructuredGrid* grid, const std::string& mode)
{
  const std::string path = havstest::OutputDir() + "/TestHAVSExpat_" + mode + ".vtu";
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(path.c_str());
  if (mode == "ascii")
  {
    writer->SetDataModeToAscii();
  }
  else if (mode == "binary")
  {
    writer->SetDataModeToBinary();
  }
  else
  {
    writer->SetDataModeToAppended();
    writer->SetEncodeAppendedData(mode == "appended-base64");
  }
  if (!writer->Write())
  {
    std::cerr << "  " << mode << ": the writer failed" << std::endl;
    return false;
  }
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkUnstructuredGrid* read = reader->GetOutput();
  bool same = read->GetNumberOfCells() == grid->GetNumberOfCells() &&
    read->GetNumberOfPoints() == grid->GetNumberOfPoints();
  vtkDataArray* a = grid->GetPointData()->GetArray("s");
  vtkDataArray* b = read->GetPointData()->GetArray("s");
  same = same && b && b->GetNumberOfTuples() == a->GetNumberOfTuples();
  for (vtkIdType i = 0; same && i < a->GetNumberOfTuples(); ++i)
  {
    same = a->GetTuple1(i) == b->GetTuple1(i);
  }
  std::cout << "  " << mode << ": read back " << read->GetNumberOfCells() << " of "
            << grid->GetNumberOfCells() << " cells, " << read->GetNumberOfPoints() << " of "
            << grid->GetNumberOfPoints() << " points: " << (same ? "same" : "DIFFERENT")
            << std::endl;
  return same;
}
}

int main(int argc, char* argv[])
{
  const std::string mode = argc > 1 ? argv[1] : "fixed";
  if (mode != "fixed" && mode != "unfixed")
  {
    std::cerr << "usage: TestHAVSExpat fixed|unfixed" << std::endl;
    return EXIT_FAILURE;
  }
  const bool deferral = dlsym(RTLD_DEFAULT, "XML_SetReparseDeferralEnabled") != nullptr;
  const long before = FixedParsers();
  std::cout << "expat: " << ExpatVersion() << " (Debian libexpat1 " << DebianExpatPackage()
            << "), reparse deferral: " << (deferral ? "yes" : "no")
            << ", vtkHAVSExpatFix in this process: " << (before >= 0 ? "yes" : "no") << std::endl;
  if (mode == "fixed" && before < 0)
  {
    std::cerr << "FAIL: the 'fixed' run does not carry vtkHAVSExpatFix." << std::endl;
    return EXIT_FAILURE;
  }
  if (mode == "unfixed" && before >= 0)
  {
    std::cerr << "FAIL: the control carries vtkHAVSExpatFix." << std::endl;
    return EXIT_FAILURE;
  }

  auto grid = vtkHAVSDataSets::MakeBox(12, 12, 12, 0.1, 0.0, 1.0);
  int same = 0;
  const char* const modes[] = { "appended-raw", "appended-base64", "binary", "ascii" };
  for (const char* m : modes)
  {
    same += RoundTrip(grid, m) ? 1 : 0;
  }
  const bool allSame = same == 4;
  const long after = FixedParsers();
  if (after >= 0)
  {
    std::cout << "vtkHAVSExpatFix turned reparse deferral off in " << after << " parsers"
              << std::endl;
  }

  if (mode == "fixed")
  {
    if (!allSame)
    {
      std::cerr << "FAIL: with vtkHAVSExpatFix, VTK's XML reader still cannot read back what "
                   "its writer wrote (expat "
                << ExpatVersion() << ", reparse deferral " << (deferral ? "on" : "absent") << ")."
                << std::endl;
      return EXIT_FAILURE;
    }
    if (deferral && after <= 0)
    {
      std::cerr << "FAIL: this expat defers reparsing but the fix touched no parser." << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "PASS: every round trip reads back the grid." << std::endl;
    return EXIT_SUCCESS;
  }
  // VTK turns the deferral off itself from 9.3 on (VTK issue 19258; Debian 13's
  // ParaView 5.13 and VTK 9.3.0 carry the patch): there the control must read
  // everything without the fix.
  const bool vtkTurnsDeferralOff = vtkVersion::GetVTKMajorVersion() > 9 ||
    (vtkVersion::GetVTKMajorVersion() == 9 && vtkVersion::GetVTKMinorVersion() >= 3);
  std::cout << "VTK " << vtkVersion::GetVTKVersion()
            << (vtkTurnsDeferralOff ? ": turns reparse deferral off itself"
                                    : ": does not turn reparse deferral off (VTK < 9.3)")
            << std::endl;
  if (deferral && vtkTurnsDeferralOff)
  {
    if (!allSame)
    {
      std::cerr << "FAIL (control): this VTK should read what it wrote with this expat, "
                   "without the fix, but does not."
                << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "PASS (control): this expat defers reparsing and this VTK handles it: no fix "
                 "is needed here."
              << std::endl;
    return EXIT_SUCCESS;
  }
  if (deferral)
  {
    if (allSame)
    {
      std::cerr << "FAIL (control): this expat defers reparsing, yet VTK's reader read every "
                   "file without the fix: the fix would not be needed and its test proves "
                   "nothing."
                << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "PASS (control): without the fix, this expat breaks VTK's XML reader (" << 4 - same
              << " of 4 encodings), as expected." << std::endl;
    return EXIT_SUCCESS;
  }
  if (!allSame)
  {
    std::cerr << "FAIL (control): this expat has no reparse deferral, yet VTK's XML reader "
                 "cannot read back what its writer wrote."
              << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "PASS (control): this expat has no reparse deferral; no fix is needed here."
            << std::endl;
  return EXIT_SUCCESS;
}
