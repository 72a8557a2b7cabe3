// relgeo/boolean.h — Booleans of closed triangle meshes under any
// IntersectionKernel_3 (boolean/mesh_boolean.h), with their result types,
// certified operands that are not checked again (boolean/valid_solid.h), and
// CSG trees of many solids (boolean/csg.h).
#pragma once

#include "relgeo/boolean/boolean_types.h"
#include "relgeo/boolean/csg.h"
#include "relgeo/boolean/mesh_boolean.h"
#include "relgeo/boolean/valid_solid.h"
