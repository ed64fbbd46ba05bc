#pragma once
#include <whiskermap/model/Leg.h>
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/model/OrientedRect.h>
#include <whiskermap/model/Table.h>
#include <whiskermap/model/Wall.h>
#include <whiskermap/obs/Shapelet.h>

namespace whiskermap::model
{
/** The densities of the generative model (paper section 3), all as natural logarithms.
 *  Each function is one equation; its number is in the comment. */

/** log(exp(a) + exp(b)) without overflow. */
double logSumExp(double a, double b);

/** Noisy-OR of one explicit cause and the null cause, as the sum of densities (eq. 12). */
inline double logNoisyOr(double logCause, double logNull) { return logSumExp(logCause, logNull); }

/** Probability of a hypothesis cell of half-width delta in (x, y, theta): (2 delta)^3 p (eq. 19). */
double logCell(double logDensity, const ModelParams& p);

/** Flat table prior p(T) = c_T (eq. 4). */
double logTablePrior(const ModelParams& p);
/** The same with the table's class and size: c_T P(class) (eq. 4 with the catalogue's class
 *  prior) times eq. 24's size term. */
double logTablePrior(const Table& t, const ModelParams& p);
/** The size prior relative to the class's nominal size (eq. 24):
 *  -(d_length^2 + d_width^2) / (2 size_sigma^2), plus logLegPrior; 0 without a catalogue. */
double logSizePrior(const Table& t, const ModelParams& p);
/** The prior of a table's leg width and texture about its class's (eq. 26):
 *  -(w - w_k)^2 / (2 leg_width_sigma^2) - (tau - tau_k)^2 / (2 texture_sigma^2), a term
 *  only where the class's spread is > 0; 0 without a catalogue. */
double logLegPrior(const Table& t, const ModelParams& p);

/** Centre of corner i in 0..3 of a table (its class's length and width): (+,+), (-,+), (-,-), (+,-) in the table frame. */
void tableCorner(const Table& t, int i, const ModelParams& p, double& x, double& y);
/** All four corners at once (one sine and cosine). */
void tableCorners(const Table& t, const ModelParams& p, double x[4], double y[4]);
/** The corner of `x, y` (four corners) nearest to the point (px, py), and its squared distance. */
int nearestCorner(const double x[4], const double y[4], double px, double py, double& d2);

/** Footprint (length x width) of a table, and the rectangle of a leg. */
OrientedRect tableRect(const Table& t, const ModelParams& p);
OrientedRect legRect(const Leg& l);

/** log p(L | T) = log alpha_L - Delta_TL (eqs. 5-6), and the corner achieving the min. */
struct LegFit
{
	double logDensity;
	int corner;
};
LegFit logLegGivenTable(const Leg& l, const Table& t, const ModelParams& p);

/** Variance of contact s's position along the unit direction (ux, uy): sigma_r^2 (eq. 7),
 *  or with p.shaft_noise and a known shaft sigma_r^2 (u . shaft)^2 + sigma_across^2. */
double contactVariance(const obs::Shapelet& s, double ux, double uy, const ModelParams& p);
/** contactVariance under shaft noise, whatever p.shaft_noise says: sigma_r^2 (u . shaft)^2 +
 *  sigma_across^2, or sigma_r^2 for a contact without a known shaft. */
double shaftVariance(const obs::Shapelet& s, double ux, double uy, const ModelParams& p);

/** log((w + sqrt(pi v)) / (leg_width + sqrt(pi v))): minus the log of eq. 7's density of a
 *  contact's position along a face of length w (excess variance v), relative to the model's
 *  leg_width (doc/model.md, "Leg width and texture"). */
double alongFaceNormaliser(double faceLength, double variance, const ModelParams& p);

/** log p(S | L) = log alpha_S - Delta_LS (eq. 7). The leg's face that explains the contact
 *  best counts: r is the exact distance to that face (a segment of the perimeter) and the
 *  normal is compared with its outward normal (mod 360 deg). Away from the corners that is
 *  the nearest face; near a corner it keeps a contact whose position noise crossed the
 *  corner's bisector on the face its normal names (doc/model.md). Where some class's leg
 *  width is inferred (ModelParams::legWidthsVary), each face's cost adds its alongFaceNormaliser. */
double logShapeletGivenLeg(const obs::Shapelet& s, const Leg& l, const ModelParams& p);

/** log p(S | W) = log alpha_S - Delta_WS (eq. 22): the wall's face that explains the contact
 *  best, of its two long faces and two end caps (Wall::hit); r^2 = across^2 + excess^2
 *  (distance to the face segment) over sigma_r^2 as eq. 7, the normal against the face's
 *  outward normal (mod 360 deg) as eq. 7, texture as eq. 7. Under shaft noise the across term
 *  uses contactVariance (and its log-ratio gain). */
double logShapeletGivenWall(const obs::Shapelet& s, const Wall& w, const ModelParams& p);
/** The same with the wall's frame (Wall::frame(), Blackboard::wallFrame()). */
double logShapeletGivenWall(const obs::Shapelet& s, const Wall& w, const Wall::Frame& fr, const ModelParams& p);
/** The face (+1 or -1 a long face, +2 or -2 an end cap: Wall::hit) of eq. 22's minimum for
 *  contact s. */
int bestWallFace(const obs::Shapelet& s, const Wall& w, const ModelParams& p);
/** The same with the wall's frame (Wall::frame()) computed once by a caller querying it again. */
int bestWallFace(const obs::Shapelet& s, const Wall& w, const Wall::Frame& fr, const ModelParams& p);

/** Cell probability of a wall (eq. 23): (2 delta)^4 c_W exp(-length / lambda_W), a density over
 *  (centre x, centre y, yaw, length) with an exponential length prior. */
double logWallPrior(const Wall& w, const ModelParams& p);

/** Null causes: a leg without a table (eq. 8), a shapelet without a leg (eq. 9). */
double logLegNull(const ModelParams& p);
double logShapeletNull(const ModelParams& p);
}  // namespace whiskermap::model
