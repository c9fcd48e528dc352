/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSExpatFix.c

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/*
 * Turns expat's reparse deferral off for the parsers VTK creates.
 *
 * Why: expat 2.6.0 (and the Debian 12 security update 2.5.0-1+deb12u5, which
 * backports it for CVE-2023-52425) defers reparsing a token that is split
 * across XML_Parse calls. VTK 9.2 and 9.3.0's vtkXMLDataParser feeds the file
 * in blocks and relies on the parser having consumed every complete token of a
 * block (to find where the appended binary data starts); with the deferral it
 * reports "not well-formed (invalid token)" or reads 0 cells, so no .vtu can be
 * read and ParaView cannot redistribute a grid between MPI ranks (VTK issue
 * 19258; VTK 9.3.1 calls XML_SetReparseDeferralEnabled(parser, XML_FALSE)
 * itself, which is what this does for the VTK that lacks it).
 *
 * How: this file defines XML_ParserCreate, the only parser constructor VTK's
 * XML parsers call. Linked into an executable that exports its symbols (the
 * vtkHAVS apps) or preloaded (LD_PRELOAD=libvtkHAVSExpatFix.so, for ParaView's
 * executables and Python), it is found before libexpat's: it creates the
 * parser with the real function and turns the deferral off when this expat has
 * it. With an expat that has no reparse deferral it changes nothing. Other
 * constructors (XML_ParserCreate_MM, used by Python's pyexpat; the NS variant)
 * are left alone, so other users of expat keep the mitigation.
 */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dlfcn.h>
#include <stddef.h>

typedef void* (*vtkHAVSParserCreate)(const char* encoding);
typedef unsigned char (*vtkHAVSSetReparseDeferral)(void* parser, unsigned char enabled);

/* How many parsers had the deferral turned off (read by the tests). */
static unsigned long vtkHAVSExpatFixParsers = 0;

__attribute__((visibility("default"))) unsigned long vtkHAVSExpatFixParserCount(void)
{
  return vtkHAVSExpatFixParsers;
}

/* Whether this expat defers reparsing (XML_SetReparseDeferralEnabled exists). */
__attribute__((visibility("default"))) int vtkHAVSExpatHasReparseDeferral(void)
{
  return dlsym(RTLD_DEFAULT, "XML_SetReparseDeferralEnabled") != NULL;
}

/* The real expat: the next XML_ParserCreate after this one in the global
 * scope, or, when expat is not global (it came with a library loaded by
 * dlopen, e.g. Mesa's DRI driver in an X server), libexpat.so.1 itself. */
static void* vtkHAVSRealExpat(const char* name)
{
  static void* library = NULL;
  void* f = dlsym(RTLD_NEXT, name);
  if (!f)
  {
    if (!library)
    {
      library = dlopen("libexpat.so.1", RTLD_NOW | RTLD_LOCAL);
    }
    f = library ? dlsym(library, name) : NULL;
  }
  return f;
}

__attribute__((visibility("default"))) void* XML_ParserCreate(const char* encoding)
{
  vtkHAVSParserCreate create = (vtkHAVSParserCreate)vtkHAVSRealExpat("XML_ParserCreate");
  vtkHAVSSetReparseDeferral setDeferral =
    (vtkHAVSSetReparseDeferral)vtkHAVSRealExpat("XML_SetReparseDeferralEnabled");
  void* parser = create ? create(encoding) : NULL;
  if (parser && setDeferral && setDeferral(parser, 0))
  {
    ++vtkHAVSExpatFixParsers;
  }
  return parser;
}
