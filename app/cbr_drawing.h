// Field drawings of case-based action selection (Ros et al. 2009) for `foresight cbr`: a
// retrieval (the problem, the retrieved case's scopes moved to the problem's ball as in Fig. 2b,
// the adapted positions with the walks to them as in Fig. 5, the fuzzy ball path as its exp(-1)
// trapezoids as in Fig. 7 and 8) and a single case with its gameplay (the atlas).
#pragma once

#include <string>

#include "app/cbr_retrieve_output.h"
#include "cbr/case.h"
#include "cbr/retrieval_params.h"
#include "models/field_spec.h"

namespace foresight {

// The whole SVG document of `foresight cbr retrieve --svg`.
std::string CbrRetrieveSvg(const CbrRetrieveRun& run, const FieldSpec& field);

// One case on the field at `pixels_per_m`: ball and scope, opponents and their scopes, teammates
// with their gameplay (walks, dribbles, passes and kicks as arrows) and the ball path built by
// retrieval's ball-path builder on the case's own problem. A non-empty `warning` is written in
// red above the field, right of the case's name.
std::string CaseSvg(const Case& c, const FieldSpec& field, const RetrievalParams& params,
                    double pixels_per_m, const std::string& warning);

}  // namespace foresight
