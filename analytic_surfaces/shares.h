/* Shares at concave folds (docs/conventions.md, "Shares at concave folds"): the rule that
 * both kinds of surface follow, in one place. Where a sphere overlaps two or more
 * contacts across a concave fold, each contact takes a share of what it exchanges. The
 * folds are where a contact may begin or end while the sphere overlaps it: the concave
 * edges and vertices of a mesh (src/faceted/mesh_query.c, hit_weights), the fold lines
 * of the contacts' tangent planes for the other kinds (rs_contacts_fold_shares). A fold
 * that the sphere reaches, cutting it in a chord (or a disc) of half-length kappa, cuts
 * the weight of each contact whose foot lies s < kappa from it by s / kappa
 * (rs_fold_cut); a contact's weight is then a^2 = R^2 - dist^2 times those cuts, and
 * rs_contacts_patch_shares makes the weights shares. Private to the geometry layer. */
#ifndef RS_SHARES_H
#define RS_SHARES_H

/// The fold rule's cut of weight *w for a foot s from a fold of half-chord kappa.
static inline void rs_fold_cut(double *w, double s, double kappa)
{
    if (s < kappa)
        *w *= s / kappa;
}

#endif
