/* The effective mass of a convex body's contact points, which the contact block hands a
 * law in place of the body's mass (docs/conventions.md, "Effective mass of a body's
 * contacts"). Private to the contact core. */
#ifndef RS_EFFECTIVE_MASS_H
#define RS_EFFECTIVE_MASS_H

#include "rigidsurf/contact_block.h"

/// For each contact of o on a convex body of p (p->body, its shape set), its effective
/// mass into cb->mass: 1 / s with s the normal velocity of the contact point per unit
/// normal impulse at each of the body's contacts that push (overlapping, each impulse
/// times its share w), s_e = n_e.N / m + (r_e x n_e).I^-1 U, N = sum w_f n_f and U = sum
/// w_f (r_f x n_f) (r the contact point less the centre of mass, I^-1 the inverse inertia
/// in the world), at least w_e s_alone / (number that push), where s_alone = 1 / m +
/// (r_e x n_e).I^-1 (r_e x n_e) is the value of the point alone. A contact that does not
/// push gets 1 / s_alone. Spheres and points keep their mass.
void rs_cblock_body_masses(rs_contact_block *cb, const rs_track_out *o,
                           const rs_block_particles *p);

#endif
