"""A synthetic layer sweep table for the layer-stats tests (test_option_effect.py,
test_range_edges.py, test_frontend_parity.py): 6 R_b/R_m x 5 heights x 4 points,
bouncing below H = 3 + 2 R_b/R_m + 0.3 point (the fourth point always bounces), so
that its diagram has a boundary for B.31 to fit."""

COLUMNS = ("x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,penetration,penetration_rm,dissipated_first_contact,"
           "block_loss_first_contact,energy_error,wave_speed,t_end,steps")


def write_bouncing_diagram(path):
    with open(path, "w") as f:
        f.write("# param vi = 20\ncase,rb-rm,height-rm,point,%s\n" % COLUMNS)
        k = 0
        for x in (0.5, 1, 1.5, 2, 3, 4):
            for h in (3, 6, 9, 12, 15):
                for pt in range(4):
                    b = 1 if (h < 3 + 2 * x + 0.3 * pt or pt == 3) else 0
                    f.write("%d,%g,%g,%d,%g,%d,0.5,0.6,10,20,10,12,0.6,%g,0.001,0.6,1e-6,nan,0.01,100\n"
                            % (k, x, h, pt, 0.05 * pt, b, 1.5 + 0.1 * pt))
                    k += 1


def write_no_diagram(path):
    """4 cases over rb-rm alone: no bouncing diagram (that needs rb-rm and
    height-rm), so the B.31 options (fit, gamma-deg, delta-rm) have no effect."""
    with open(path, "w") as f:
        f.write("# param vi = 20\ncase,rb-rm,point,%s\n" % COLUMNS)
        for k in range(4):
            f.write("%d,%g,%d,0,%d,0.5,0.6,10,20,10,12,0.6,1.5,0.001,0.6,1e-6,nan,0.01,100\n"
                    % (k, 1 + (k // 2) * 0.5, k % 2, k % 2))
