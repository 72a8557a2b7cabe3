// tools/relgeo/commands/commands.h — every command: its options, the function
// declaring them (commands/<command>/options.cpp), the function running it
// (command.cpp) and its help footer. main.cpp registers each in one line.
#pragma once

#include "commands/boolean/command.h"
#include "commands/csg/command.h"
#include "commands/experiment/command.h"
#include "commands/extrusion/command.h"
#include "commands/hull/command.h"
#include "commands/join/command.h"
#include "commands/linsolve/command.h"
#include "commands/orient_grid/command.h"
#include "commands/subdivide/command.h"
