// 4-point Gauss-Legendre rule on [-1, 1] (nodes +-GAUSS_NODE[i], weights
// GAUSS_WEIGHT[i]): exact for polynomials up to degree 7.
const float GAUSS_NODE[2] = float[2](0.3399810435848563, 0.8611363115940526);
const float GAUSS_WEIGHT[2] = float[2](0.6521451548625461, 0.3478548451374538);
