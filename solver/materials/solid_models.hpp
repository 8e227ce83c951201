// The list of solid constitutive models: one line per model. It drives the scene reader (the
// "model" values it accepts and the error listing them), the particle builder's initial state and
// the stress update's dispatch (one std::visit per particle). Adding a model: its file in this
// folder (see solid_model.hpp for what it provides) and its line here.
#pragma once
#include <variant>

#include "materials/drucker_prager.hpp"
#include "materials/linear_elastic.hpp"
#include "materials/modified_cam_clay.hpp"
#include "materials/mu_i.hpp"
#include "materials/mohr_coulomb.hpp"
#include "materials/von_mises.hpp"

namespace geosph::materials {

using SolidModel = std::variant<
    DruckerPrager,
    ModifiedCamClay,
    LinearElastic,
    VonMises,
    MohrCoulomb,
    MuI>;

}  // namespace geosph::materials
