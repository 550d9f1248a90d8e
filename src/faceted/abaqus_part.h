/* An Abaqus rigid part (*NODE, *ELEMENT, TYPE=R3D3|R3D4, *INCLUDE) as a polygon soup. */
#ifndef RS_ABAQUS_PART_H
#define RS_ABAQUS_PART_H

#include "cgal_mesh.h"

/// Reads the rigid part of Abaqus input file path (and the files it includes) into soup:
/// its nodes, and one polygon per R3D3 or R3D4 element in node order. Returns 0, or -1
/// with "FILE:LINE: what was expected" in msg.
int rs_abaqus_read_soup(const char *path, rs_soup *soup, char *msg, size_t cap);

#endif
