/* HylcYarnModel: yarn material and contact parameters with options and documented defaults. */
#include <hylc/options.h>
#include <hylc/yarn.h>

static const char *const ContactTypes[]   = {"quadrature", "closest", "HylcContactType", "HYLC_CONTACT_", NULL};
static const char *const CurvatureTypes[] = {"averaged", "per_edge", "HylcRodCurvatureVariant", "HYLC_ROD_CURVATURE_", NULL};

/*@C
  HylcYarnModelDefault - The default yarn model (docs/method.md §11): E = 1e6 Pa, Es = E, G = E/2.5,
  kc = 0.7 E r, the pattern's radius, the quadrature contact with 4 points per segment, an exclusion arc of
  3 r, the averaged-frame curvature.

  Not collective

  Output Parameter:
. m - the model

  Level: beginner

.seealso: HylcYarnModelSetFromOptions(), HylcYarnModelGetConstants()
@*/
PetscErrorCode HylcYarnModelDefault(HylcYarnModel *m)
{
  PetscFunctionBegin;
  PetscCall(PetscMemzero(m, sizeof(*m)));
  m->E             = 1.0e6; /* the 0.1 mm patterns' value (docs/method.md §11) */
  m->Es            = 0;     /* = E */
  m->G             = 0;     /* = E / 2.5 */
  m->kc            = 0;     /* = 0.7 E r */
  m->radius        = 0;     /* the pattern's */
  m->contactPoints = 4;
  m->contactType   = HYLC_CONTACT_QUADRATURE;
  m->excludeArc    = 3.0;
  m->curvature     = HYLC_ROD_CURVATURE_AVERAGED;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcYarnModelSetFromOptions - Reads the yarn model options after the given options prefix.

  Collective

  Input Parameters:
+ comm   - the communicator the options are read on
- prefix - the options prefix (NULL: none): -<prefix>yarn_*

  Input/Output Parameter:
. m - the model: its values are the defaults of the options, replaced by those given

  Options Database Keys:
+ -yarn_E <1e6>                  - bending Young's modulus (Pa); B = E pi r^4/4
. -yarn_Es <E>                   - stretching modulus (Pa); k_s = Es pi r^2
. -yarn_G <E/2.5>                - shear modulus (Pa); beta = G pi r^4/2
. -yarn_kc <0.7 E r>             - contact stiffness (N/m)
. -yarn_radius <pattern's>       - override the pattern's yarn radius (m)
. -yarn_contact_points <4>       - Gauss points per segment (quadrature contact), 1..16
. -yarn_contact_type <quadrature> - quadrature or closest
. -yarn_exclude_arc <3>          - same-yarn segment pairs closer than this rest arc length (units of r) do not interact
- -yarn_curvature <averaged>     - averaged or per_edge material curvature

  Level: beginner

.seealso: HylcYarnModelDefault(), HylcYarnModelView()
@*/
PetscErrorCode HylcYarnModelSetFromOptions(MPI_Comm comm, const char prefix[], HylcYarnModel *m)
{
  PetscEnum ct = (PetscEnum)m->contactType, cv = (PetscEnum)m->curvature;

  PetscFunctionBegin;
  PetscOptionsBegin(comm, prefix, "Yarn material and contact model", "HylcYarnModel");
  PetscCall(HylcOptionsReal("-yarn_E", "Bending Young's modulus (Pa)", "HylcYarnModel", m->E, &m->E, NULL));
  PetscCall(HylcOptionsReal("-yarn_Es", "Stretching modulus (Pa); 0 = E", "HylcYarnModel", m->Es, &m->Es, NULL));
  PetscCall(HylcOptionsReal("-yarn_G", "Shear modulus (Pa); 0 = E/2.5", "HylcYarnModel", m->G, &m->G, NULL));
  PetscCall(HylcOptionsReal("-yarn_kc", "Contact stiffness (N/m); 0 = 0.7 E r", "HylcYarnModel", m->kc, &m->kc, NULL));
  PetscCall(HylcOptionsReal("-yarn_radius", "Yarn radius override (m); 0 = the pattern's", "HylcYarnModel", m->radius, &m->radius, NULL));
  PetscCall(HylcOptionsInt("-yarn_contact_points", "Gauss points per segment for the quadrature contact", "HylcYarnModel", m->contactPoints, &m->contactPoints, NULL));
  PetscCall(HylcOptionsEnum("-yarn_contact_type", "Contact energy: quadrature (integral over both segments) or closest (one closest-point sample)", "HylcYarnModel", ContactTypes, ct, &ct, NULL));
  PetscCall(HylcOptionsReal("-yarn_exclude_arc", "Same-yarn pairs closer than this rest arc length (units of r) do not interact", "HylcYarnModel", m->excludeArc, &m->excludeArc, NULL));
  PetscCall(HylcOptionsEnum("-yarn_curvature", "Material curvature convention", "HylcYarnModel", CurvatureTypes, cv, &cv, NULL));
  PetscOptionsEnd();
  m->contactType = (HylcContactType)ct;
  m->curvature   = (HylcRodCurvatureVariant)cv;
  PetscCheck(m->E > 0, comm, PETSC_ERR_USER_INPUT, "-yarn_E must be positive, got %g", (double)m->E);
  PetscCheck(m->Es >= 0 && m->G >= 0 && m->kc >= 0 && m->radius >= 0, comm, PETSC_ERR_USER_INPUT, "-yarn_Es, -yarn_G, -yarn_kc and -yarn_radius must not be negative (0 selects the default)");
  PetscCheck(m->contactPoints >= 1 && m->contactPoints <= 16, comm, PETSC_ERR_USER_INPUT, "-yarn_contact_points must be in 1..16, got %" PetscInt_FMT, m->contactPoints);
  PetscCheck(m->excludeArc >= 0, comm, PETSC_ERR_USER_INPUT, "-yarn_exclude_arc must not be negative, got %g", (double)m->excludeArc);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcYarnModelGetConstants - The constants of the model for a yarn of the pattern's radius: the radius (the
  model's override if set), the moduli with their defaults resolved, k_s = Es pi r^2, B = E pi r^4/4,
  beta = G pi r^4/2 and kc.

  Not collective

  Input Parameters:
+ m             - the model
- patternRadius - the pattern's yarn radius (m)

  Output Parameter:
. c - the constants

  Level: intermediate

.seealso: HylcYarnModelDefault(), HylcYarnModelView()
@*/
PetscErrorCode HylcYarnModelGetConstants(const HylcYarnModel *m, PetscReal patternRadius, HylcYarnConstants *c)
{
  PetscFunctionBegin;
  c->r    = m->radius > 0 ? m->radius : patternRadius;
  c->E    = m->E;
  c->Es   = m->Es > 0 ? m->Es : m->E;
  c->G    = m->G > 0 ? m->G : m->E / 2.5;
  c->kc   = m->kc > 0 ? m->kc : 0.7 * m->E * c->r;
  c->ks   = HylcRodStretchStiffness(c->Es, c->r);
  c->B    = HylcRodBendStiffness(c->E, c->r);
  c->beta = HylcRodTwistStiffness(c->G, c->r);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcYarnModelView - Prints the model's constants for a yarn of the pattern's radius (two lines).

  Collective on the viewer

  Input Parameters:
+ m             - the model
. patternRadius - the pattern's yarn radius (m)
- viewer        - an ASCII viewer

  Level: intermediate

.seealso: HylcYarnModelGetConstants()
@*/
PetscErrorCode HylcYarnModelView(const HylcYarnModel *m, PetscReal patternRadius, PetscViewer viewer)
{
  HylcYarnConstants c;

  PetscFunctionBegin;
  PetscCall(HylcYarnModelGetConstants(m, patternRadius, &c));
  PetscCall(PetscViewerASCIIPrintf(viewer, "yarn model: r = %g m, E = %g Pa, Es = %g Pa, G = %g Pa, kc = %g N/m\n", (double)c.r, (double)c.E, (double)c.Es, (double)c.G, (double)c.kc));
  PetscCall(PetscViewerASCIIPrintf(viewer, "  ks = %g N, B = %g N m^2, beta = %g N m^2; contact %s (%" PetscInt_FMT " points), exclusion arc %g r, %s curvature\n", (double)c.ks, (double)c.B, (double)c.beta, ContactTypes[m->contactType],
                                   m->contactPoints, (double)m->excludeArc, CurvatureTypes[m->curvature]));
  PetscFunctionReturn(PETSC_SUCCESS);
}
