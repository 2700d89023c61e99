/*
 * A peer for the trade report: the textbook way to simulate a bouncing contact without an
 * event-driven solver. The stop is a stiff spring-dashpot (penalty contact) and the motion is
 * integrated by classical RK4 at a fixed step, in C.
 *
 * One body against a stop (the model of the core): y = x - Delta, free flight
 *   y'' = -2 zeta Omega y' - Omega^2 (y + Delta)            (y <= 0)
 * and in contact (y > 0) the penalty force per unit mass
 *   -omega_c^2 y - 2 zeta_c omega_c y',   omega_c = beta Omega,
 * with zeta_c = -ln R / sqrt(pi^2 + ln^2 R), so that an isolated linear contact returns at R
 * times its entry speed. The contact lasts about pi / omega_c at every impact, whatever its
 * speed, so a penalty model shifts each impact by that much: beta must grow until the shift
 * summed over the impacts that matter is below the accuracy asked. The step is a fixed
 * fraction of the contact time; a step across y = 0 (where the force has a kink, which would
 * cost RK4 its order) is split at the crossing, found by secant steps on the step fraction.
 *
 * The body enters the stop at t = 0 with speed v0. The result is the time of the last entry
 * into contact after which the body never leaves it again (it stays in contact for more than
 * 20 contact times): the end of the bounce. Returns -1 if that does not happen before t_max.
 */
#include <math.h>

typedef struct {
    double damping, w2, delta, damping_c, wc2;
} model;

static double accel(const model *m, int contact, double y, double v) {
    double a = -m->damping * v - m->w2 * (y + m->delta);
    return contact ? a - m->wc2 * y - m->damping_c * v : a;
}

/* One RK4 step of length h with the force law of `contact` fixed. */
static void step(const model *m, int contact, double h, double *y, double *v) {
    double k1y = *v, k1v = accel(m, contact, *y, *v);
    double y2 = *y + 0.5 * h * k1y, v2 = *v + 0.5 * h * k1v;
    double k2y = v2, k2v = accel(m, contact, y2, v2);
    double y3 = *y + 0.5 * h * k2y, v3 = *v + 0.5 * h * k2v;
    double k3y = v3, k3v = accel(m, contact, y3, v3);
    double y4 = *y + h * k3y, v4 = *v + h * k3v;
    double k4y = v4, k4v = accel(m, contact, y4, v4);
    *y += h / 6.0 * (k1y + 2.0 * k2y + 2.0 * k3y + k4y);
    *v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
}

double penalty_rk4_end(double omega, double delta, double restitution, double zeta, double v0,
                       double beta, double steps_per_contact, double t_max) {
    const double pi = 3.14159265358979323846;
    const double omega_c = beta * omega;
    const double log_r = log(restitution);
    const double zeta_c = -log_r / sqrt(pi * pi + log_r * log_r);
    const double contact_time = pi / omega_c;
    const double h = contact_time / steps_per_contact;
    const model m = {2.0 * zeta * omega, omega * omega, delta, 2.0 * zeta_c * omega_c,
                     omega_c * omega_c};
    double y = 0.0, v = v0, t = 0.0, entry = 0.0;
    int contact = 1;
    long n = 0;
    while (t < t_max) {
        double y1 = y, v1 = v;
        step(&m, contact, h, &y1, &v1);
        int crossed = contact ? (y1 <= 0.0) : (y1 > 0.0);
        if (!crossed) {
            y = y1;
            v = v1;
        } else {
            /* Secant on the fraction s of the step where y = 0, each trial integrated from the
             * step's start with the old force law. */
            double s0 = 0.0, f0 = y, s1 = 1.0, f1 = y1;
            for (int k = 0; k < 4 && f1 != f0; k++) {
                double s = s1 - f1 * (s1 - s0) / (f1 - f0);
                if (!(s > 0.0 && s < 1.0)) {
                    break;
                }
                double ys = y, vs = v;
                step(&m, contact, s * h, &ys, &vs);
                s0 = s1;
                f0 = f1;
                s1 = s;
                f1 = ys;
            }
            double s = (s1 > 0.0 && s1 < 1.0) ? s1 : 0.5;
            step(&m, contact, s * h, &y, &v);
            y = 0.0;
            contact = !contact;
            if (contact) {
                entry = t + s * h;
            }
            step(&m, contact, (1.0 - s) * h, &y, &v);
        }
        n++;
        t = (double)n * h;
        if (contact && t - entry > 20.0 * contact_time) {
            return entry;
        }
    }
    return -1.0;
}
