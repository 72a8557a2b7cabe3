// relgeo/io.h — relgeo's file formats: point files, JSON reports and
// reading, contour JSON, SVG and PNG pictures (umbrella of relgeo/io/).
//
// point_file.h, svg_canvas.h, text_file.h and number_text.h need nothing but
// relgeo::relgeo; json.h, contour_json.h and png.h need nlohmann-json and
// stb: link relgeo::io, which brings both (this umbrella includes all).
#pragma once

#include "relgeo/io/contour_json.h"
#include "relgeo/io/errors.h"
#include "relgeo/io/json.h"
#include "relgeo/io/number_text.h"
#include "relgeo/io/png.h"
#include "relgeo/io/point_file.h"
#include "relgeo/io/svg_canvas.h"
#include "relgeo/io/text_file.h"
#include "relgeo/io/xml_text.h"
